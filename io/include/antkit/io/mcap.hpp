#pragma once
// MCAP files (https://mcap.dev/spec), the container Foxglove and rosbag2 read: a writer of
// indexed, uncompressed files, written from the specification (no MCAP library is in Debian).
//
// The file it writes, in this order:
//   magic, Header (profile, library), the data section: Schema and Channel records as they are
//   added, Messages in Chunks (compression "", the CRC-32 of the records) each followed by one
//   MessageIndex per channel it holds (channel id order); DataEnd (the CRC-32 of every byte before
//   it); the summary section, grouped by opcode: Schemas, Channels, one Statistics, ChunkIndexes;
//   one SummaryOffset per group; Footer (the CRC-32 of the summary from its start through the
//   footer's summary_offset_start); magic.
// Every integer little-endian. Nothing in the bytes depends on a clock or on memory: the same calls
// write the same file.
#include <antkit/io/crc32.hpp>
#include <cstdint>
#include <map>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace antkit::io::mcap {

inline constexpr std::string_view kMagic{"\x89MCAP0\r\n", 8};

// The record opcodes (spec, Records).
enum class Op : std::uint8_t {
  Header = 0x01,
  Footer = 0x02,
  Schema = 0x03,
  Channel = 0x04,
  Message = 0x05,
  Chunk = 0x06,
  MessageIndex = 0x07,
  ChunkIndex = 0x08,
  Statistics = 0x0B,
  SummaryOffset = 0x0E,
  DataEnd = 0x0F,
};

// CRC-32 as MCAP specifies it: zlib's (crc32.hpp).
using io::crc32;

struct Message {
  std::uint16_t channel_id = 0;
  std::uint32_t sequence = 0;
  std::uint64_t log_time = 0;     // ns
  std::uint64_t publish_time = 0; // ns; the log time when the source has no other
  std::string data;
  friend bool operator==(const Message&, const Message&) = default;
};

struct WriterOptions {
  std::string profile;                 // "" (no well-known profile's rules apply)
  std::string library = "antkit";      // fixed: no version, so the bytes do not move with one
  std::uint64_t chunk_size = 1U << 20; // a chunk is closed once its records reach this many bytes
};

// A chunk's Message records and their index, built apart from the Writer (on another thread, say,
// while the writer writes the chunk before it) and written whole by Writer::write_chunk. The same
// calls give the same bytes wherever the chunk was built.
class Chunk {
public:
  // As Writer::begin_message / end_message (below), into this chunk. Throws std::logic_error for
  // channel 0 and for the calls out of turn; other channel ids are checked by write_chunk.
  std::string& begin_message(std::uint16_t channel_id, std::uint32_t sequence,
                             std::uint64_t log_time, std::uint64_t publish_time);
  void end_message();
  void add(const Message& message);
  [[nodiscard]] bool empty() const noexcept { return messages_ == 0; }
  [[nodiscard]] std::size_t size() const noexcept { return records_.size(); } // record bytes
  [[nodiscard]] std::uint64_t messages() const noexcept { return messages_; }
  // The costly half of writing it: the records' CRC-32 and the MessageIndex records (each
  // channel's entries in log time order, stable). No message may be added after it; write_chunk
  // seals a chunk that is not sealed.
  void seal();
  // Empty again, keeping its buffers.
  void clear() noexcept;

private:
  friend class Writer;
  std::string records_;
  std::size_t message_start_ = 0; // the open message's record (begin_message)
  bool open_ = false, sealed_ = false;
  std::uint64_t start_ = 0, end_ = 0, messages_ = 0;
  // Each channel's (log time, offset in records_), by channel id.
  std::vector<std::vector<std::pair<std::uint64_t, std::uint64_t>>> index_;
  std::uint32_t crc_ = 0;     // of records_, once sealed
  std::string index_records_; // the MessageIndex records, once sealed
  std::vector<std::pair<std::uint16_t, std::uint64_t>> index_at_; // channel, offset in them
};

class Writer {
public:
  // Writes the magic and the Header to `out` at once; `out` must stay valid until finish().
  Writer(std::ostream& out, WriterOptions options = {});
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  // Ids count up from 1 in the order of the calls. A channel's schema must have been added (0 for
  // a channel without one). Throws std::logic_error for an unknown schema, a finished writer, or
  // more than 65535 schemas or channels.
  std::uint16_t add_schema(std::string_view name, std::string_view encoding, std::string_view data);
  std::uint16_t add_channel(std::uint16_t schema_id, std::string_view topic,
                            std::string_view message_encoding,
                            const std::vector<std::pair<std::string, std::string>>& metadata = {});
  // Throws std::logic_error for a channel not added.
  void write(const Message& message);
  // The same record written in place, without a copy of the data: begin_message() writes the
  // record's head into the open chunk and returns that chunk; the caller appends the message's
  // bytes to it (nothing else), then end_message() sets the record's length. Between the two no
  // other call may be made (std::logic_error).
  std::string& begin_message(std::uint16_t channel_id, std::uint32_t sequence,
                             std::uint64_t log_time, std::uint64_t publish_time);
  void end_message();
  // Closes the open chunk, then writes `chunk` as the next one (sealing it first if it is not)
  // and clears it. Throws std::logic_error for a message on a channel not added, an open message
  // in it, or a call between begin_message and end_message. An empty chunk writes nothing.
  void write_chunk(Chunk& chunk);
  // Closes the last chunk and writes DataEnd, the summary, its offsets, the Footer and the magic.
  void finish();

  [[nodiscard]] std::uint64_t messages() const noexcept {
    return message_count_ + chunk_.messages();
  }
  [[nodiscard]] std::uint64_t bytes() const noexcept { return position_; } // written so far
  // Each channel's topic and messages written, in channel id order.
  [[nodiscard]] std::vector<std::pair<std::string, std::uint64_t>> channel_counts() const;

private:
  struct SchemaRecord {
    std::uint16_t id;
    std::string name, encoding, data;
  };
  struct ChannelRecord {
    std::uint16_t id, schema_id;
    std::string topic, encoding;
    std::vector<std::pair<std::string, std::string>> metadata;
  };
  void emit(std::string_view bytes); // to the file, counted and (before DataEnd) into the data CRC
  void emit(std::string_view bytes, std::uint32_t crc); // the same, its CRC-32 known
  void emit_chunk(Chunk& chunk); // seals it, writes it and its index, clears it
  void check_channels(const Chunk& chunk) const;

  std::ostream& out_;
  WriterOptions options_;
  std::uint64_t position_ = 0;
  std::uint32_t data_crc_ = 0;
  bool finished_ = false;
  std::vector<SchemaRecord> schemas_;
  std::vector<ChannelRecord> channels_;
  Chunk chunk_;               // the open chunk
  std::string chunk_indexes_; // the summary's ChunkIndex records so far
  std::uint32_t chunk_count_ = 0;
  std::uint64_t message_count_ = 0, start_time_ = 0, end_time_ = 0;
  std::map<std::uint16_t, std::uint64_t> channel_counts_;
};

// The record encodings (spec, Serialization), for the writer and for tests that build a record by
// hand: each appends to `out`.
void put_u8(std::string& out, std::uint8_t v);
void put_u16(std::string& out, std::uint16_t v);
void put_u32(std::string& out, std::uint32_t v);
void put_u64(std::string& out, std::uint64_t v);
void put_string(std::string& out, std::string_view s); // uint32 length, bytes
// <opcode><uint64 content length><content>
void put_record(std::string& out, Op op, std::string_view content);

} // namespace antkit::io::mcap
