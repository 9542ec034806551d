#pragma once
// Reading MCAP files (https://mcap.dev/spec), written from the specification: the data section in
// file order, its chunks uncompressed, zstd or lz4 (LZ4 frames), every CRC that the file carries
// checked (a CRC of 0 means "not computed" and is not checked). Part of the antkit_bags target
// (io/CMakeLists.txt: it links libzstd and liblz4, which antkit_io does not).
//
// The file is mapped, not read: a message's data is a view into the mapping (uncompressed chunks)
// or into the reader's buffer of the current chunk, valid until the next call to next().
//
// Bad input is a kernel::InputError located at "FILE: byte N" (N: the offset of the record or
// field that is wrong): a file that is not MCAP (magic), a truncated file, a record whose length
// runs past its end, a chunk or data section or summary whose CRC does not match, an unknown
// compression, a message on a channel never defined, a chunk whose size differs from what it says.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace antkit::io::mcap {

struct SchemaInfo {
  std::uint16_t id = 0;
  std::string name, encoding, data;
};

struct ChannelInfo {
  std::uint16_t id = 0, schema_id = 0;
  std::string topic, message_encoding;
  std::vector<std::pair<std::string, std::string>> metadata;
};

struct MessageView {
  const ChannelInfo* channel = nullptr;
  std::uint32_t sequence = 0;
  std::uint64_t log_time = 0, publish_time = 0; // ns
  std::string_view data;
  std::uint64_t offset = 0; // where the Message record starts: in the file, or in its chunk's
  bool in_chunk = false;    // records (then `chunk_offset` is the Chunk record's offset)
  std::uint64_t chunk_offset = 0;
};

struct ReaderOptions {
  bool check_crcs = true; // chunk, data section and summary CRCs
};

class Reader {
public:
  // Maps `path` and checks the leading and trailing magic, the Header and the Footer (and the
  // summary's CRC). Throws InputError(path, ...) when it cannot be read.
  explicit Reader(const std::string& path, ReaderOptions options = {});
  // The same over bytes held by the caller (fuzzing, tests); `name` stands for the file in errors.
  Reader(std::string_view bytes, std::string name, ReaderOptions options = {});
  ~Reader();
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  // The next message of the data section in file order; false at its end (DataEnd, or the Footer
  // when the file has no DataEnd). Schemas and channels are collected as they are met.
  bool next(MessageView& out);

  [[nodiscard]] const std::string& profile() const noexcept { return profile_; }
  [[nodiscard]] const std::string& library() const noexcept { return library_; }
  [[nodiscard]] const std::string& name() const noexcept { return name_; }
  [[nodiscard]] const std::map<std::uint16_t, SchemaInfo>& schemas() const noexcept {
    return schemas_;
  }
  [[nodiscard]] const std::map<std::uint16_t, ChannelInfo>& channels() const noexcept {
    return channels_;
  }
  // The schema of a channel, or nullptr (schema id 0).
  [[nodiscard]] const SchemaInfo* schema_of(const ChannelInfo& channel) const;
  // "FILE: byte N" for a message as next() returned it.
  [[nodiscard]] std::string where(const MessageView& message) const;

private:
  struct Mapping;
  void open();
  [[noreturn]] void fail(std::uint64_t offset, const std::string& what) const;
  // One record of the data section or of a chunk: its opcode and content; false at the end.
  void on_schema(std::string_view content, std::uint64_t offset);
  void on_channel(std::string_view content, std::uint64_t offset);
  void open_chunk(std::string_view content, std::uint64_t offset);

  std::unique_ptr<Mapping> mapping_;
  std::string_view file_;
  std::string name_;
  ReaderOptions options_;
  std::string profile_, library_;
  std::uint64_t pos_ = 0;      // the next record of the data section
  std::uint64_t data_end_ = 0; // where the data section's records must end (the Footer)
  bool done_ = false;
  // The data section's CRC over its first crc_pos_ bytes (uncompressed chunks are added as they
  // are read, from their own CRC; the rest at DataEnd).
  std::uint64_t crc_pos_ = 0;
  std::uint32_t data_crc_ = 0;
  std::map<std::uint16_t, SchemaInfo> schemas_;
  std::map<std::uint16_t, ChannelInfo> channels_;
  // The chunk being read: its records (a view into the file or into buffer_), the next one.
  std::string_view chunk_;
  std::uint64_t chunk_pos_ = 0, chunk_offset_ = 0;
  bool in_chunk_ = false;
  std::unique_ptr<char[]> buffer_;
  std::size_t buffer_size_ = 0;
};

} // namespace antkit::io::mcap
