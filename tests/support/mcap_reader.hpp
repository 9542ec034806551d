#pragma once
// A small MCAP reader for the tests (https://mcap.dev/spec), written from the specification as
// independently of io/mcap.cpp as one file can be: it walks the whole file and checks what the
// writer promises, throwing std::runtime_error with what is wrong and where:
//   both magics; the Header first; every record's length within the file; the data section's CRC
//   (DataEnd); each chunk's CRC, its records, its time range; the MessageIndex records after each
//   chunk, each entry at a Message of that channel and log time; each ChunkIndex at its chunk, with
//   its length, its message index offsets and length, and the sizes; the summary grouped by opcode
//   and each SummaryOffset at its group; Statistics against the messages read; the Footer's offsets
//   and summary CRC.
// Reads uncompressed chunks only (antkit writes no other).
#include <antkit/io/mcap.hpp>
#include <cstdint>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace antkit::test::mcap {

struct Schema {
  std::uint16_t id = 0;
  std::string name, encoding, data;
};
struct Channel {
  std::uint16_t id = 0, schema_id = 0;
  std::string topic, encoding;
  std::vector<std::pair<std::string, std::string>> metadata;
};
struct Statistics {
  std::uint64_t message_count = 0;
  std::uint16_t schema_count = 0;
  std::uint32_t channel_count = 0, attachment_count = 0, metadata_count = 0, chunk_count = 0;
  std::uint64_t start = 0, end = 0;
  std::map<std::uint16_t, std::uint64_t> channel_counts;
};
struct File {
  std::string profile, library;
  std::map<std::uint16_t, Schema> schemas;
  std::map<std::uint16_t, Channel> channels;
  std::vector<io::mcap::Message> messages; // in file order
  std::uint32_t chunks = 0;
  Statistics statistics;
  std::uint64_t indexed_messages = 0; // messages reached through the chunk and message indexes
};

class Cursor {
public:
  Cursor(std::string_view bytes, std::string what) : b_(bytes), what_(std::move(what)) {}
  [[nodiscard]] bool done() const noexcept { return p_ >= b_.size(); }
  [[nodiscard]] std::size_t pos() const noexcept { return p_; }
  std::uint64_t uint(int n) {
    need(static_cast<std::size_t>(n));
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i)
      v |= static_cast<std::uint64_t>(
               static_cast<std::uint8_t>(b_[p_ + static_cast<std::size_t>(i)]))
           << (8 * i);
    p_ += static_cast<std::size_t>(n);
    return v;
  }
  std::uint8_t u8() { return static_cast<std::uint8_t>(uint(1)); }
  std::uint16_t u16() { return static_cast<std::uint16_t>(uint(2)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(uint(4)); }
  std::uint64_t u64() { return uint(8); }
  std::string_view bytes(std::uint64_t n) {
    need(n);
    const auto s = b_.substr(p_, static_cast<std::size_t>(n));
    p_ += static_cast<std::size_t>(n);
    return s;
  }
  std::string str() { return std::string(bytes(u32())); }
  [[noreturn]] void fail(const std::string& why) const {
    throw std::runtime_error(what_ + " at " + std::to_string(p_) + ": " + why);
  }

private:
  void need(std::uint64_t n) const {
    if (n > b_.size() - p_)
      fail("needs " + std::to_string(n) + " bytes, " + std::to_string(b_.size() - p_) + " left");
  }
  std::string_view b_;
  std::size_t p_ = 0;
  std::string what_;
};

inline io::mcap::Message parse_message(std::string_view content) {
  Cursor c(content, "message");
  io::mcap::Message m;
  m.channel_id = c.u16();
  m.sequence = c.u32();
  m.log_time = c.u64();
  m.publish_time = c.u64();
  m.data = std::string(content.substr(c.pos()));
  return m;
}

inline File read(std::string_view file) {
  using io::mcap::Op;
  constexpr std::string_view magic{"\x89MCAP0\r\n", 8};
  if (file.size() < 16 || file.substr(0, 8) != magic || file.substr(file.size() - 8) != magic)
    throw std::runtime_error("no MCAP magic at both ends");
  File out;
  Cursor c(file.substr(0, file.size() - 8), "file");
  c.bytes(8);
  // One chunk's records, by offset, for the message indexes after it.
  struct OpenChunk {
    std::uint64_t at = 0, length = 0, records_at = 0;
    std::map<std::uint64_t, io::mcap::Message> by_offset;
    std::map<std::uint16_t, std::uint64_t> index_at; // channel -> MessageIndex offset
    std::uint64_t index_end = 0;
    std::uint64_t start = 0, end = 0, size = 0;
  };
  std::vector<OpenChunk> chunks;
  bool data_end = false, header = false;
  std::uint64_t summary_at = 0;
  std::vector<std::pair<Op, std::uint64_t>> summary_records;               // opcode, offset
  std::map<std::uint8_t, std::pair<std::uint64_t, std::uint64_t>> offsets; // group -> start, length
  std::uint64_t offsets_at = 0;
  std::vector<std::string> chunk_index_contents;
  bool statistics = false;
  for (;;) {
    const std::uint64_t at = c.pos();
    const auto op = static_cast<Op>(c.u8());
    const std::uint64_t length = c.u64();
    const std::string_view content = c.bytes(length);
    Cursor r(content, "record at " + std::to_string(at));
    if (!header) {
      if (op != Op::Header) c.fail("the first record is not the Header");
      out.profile = r.str();
      out.library = r.str();
      header = true;
      continue;
    }
    if (op == Op::Footer) {
      if (!c.done()) c.fail("bytes after the Footer");
      const std::uint64_t summary_start = r.u64(), offset_start = r.u64();
      const std::uint32_t crc = r.u32();
      if (summary_start != summary_at) c.fail("the Footer's summary_start is not the summary's");
      if (offset_start != (offsets.empty() ? 0 : offsets_at))
        c.fail("the Footer's summary_offset_start is not the offsets'");
      const std::string_view covered = file.substr(summary_at, at + 1 + 8 + 16 - summary_at);
      if (crc != io::mcap::crc32(covered)) c.fail("the summary CRC does not match");
      break;
    }
    if (!data_end) {
      switch (op) {
      case Op::Schema: {
        Schema s;
        s.id = r.u16();
        s.name = r.str();
        s.encoding = r.str();
        s.data = r.str();
        if (s.id == 0) c.fail("schema id 0");
        out.schemas[s.id] = s;
        break;
      }
      case Op::Channel: {
        Channel ch;
        ch.id = r.u16();
        ch.schema_id = r.u16();
        ch.topic = r.str();
        ch.encoding = r.str();
        Cursor m(r.bytes(r.u32()), "channel metadata");
        while (!m.done()) {
          std::string k = m.str();
          ch.metadata.emplace_back(std::move(k), m.str());
        }
        if (ch.schema_id != 0 && out.schemas.count(ch.schema_id) == 0)
          c.fail("a channel before its schema");
        out.channels[ch.id] = ch;
        break;
      }
      case Op::Chunk: {
        OpenChunk ck;
        ck.at = at;
        ck.length = c.pos() - at;
        ck.start = r.u64();
        ck.end = r.u64();
        ck.size = r.u64();
        const std::uint32_t crc = r.u32();
        if (r.str() != "") c.fail("a compressed chunk");
        const std::uint64_t n = r.u64();
        ck.records_at = at + 1 + 8 + r.pos();
        const std::string_view records = r.bytes(n);
        if (n != ck.size) c.fail("chunk sizes differ");
        if (crc != io::mcap::crc32(records)) c.fail("the chunk CRC does not match");
        Cursor in(records, "chunk at " + std::to_string(at));
        std::uint64_t lo = ~0ULL, hi = 0;
        while (!in.done()) {
          const std::uint64_t off = in.pos();
          const auto iop = static_cast<Op>(in.u8());
          const std::string_view ic = in.bytes(in.u64());
          if (iop != Op::Message) in.fail("a chunk record that is not a Message");
          auto m = parse_message(ic);
          if (out.channels.count(m.channel_id) == 0) in.fail("a message before its channel");
          lo = std::min(lo, m.log_time);
          hi = std::max(hi, m.log_time);
          out.messages.push_back(m);
          ck.by_offset[off] = std::move(m);
        }
        if (ck.by_offset.empty() || lo != ck.start || hi != ck.end)
          c.fail("the chunk's time range is not its messages'");
        ck.index_end = c.pos();
        chunks.push_back(std::move(ck));
        ++out.chunks;
        break;
      }
      case Op::MessageIndex: {
        if (chunks.empty() || chunks.back().index_end != at)
          c.fail("a MessageIndex not right after a chunk or its indexes");
        auto& ck = chunks.back();
        const std::uint16_t channel = r.u16();
        if (ck.index_at.count(channel) != 0) c.fail("two MessageIndex records for one channel");
        ck.index_at[channel] = at;
        Cursor e(r.bytes(r.u32()), "message index");
        std::uint64_t last = 0;
        while (!e.done()) {
          const std::uint64_t t = e.u64(), off = e.u64();
          if (t < last) e.fail("entries not in log time order");
          last = t;
          const auto it = ck.by_offset.find(off);
          if (it == ck.by_offset.end() || it->second.channel_id != channel ||
              it->second.log_time != t)
            e.fail("an entry not at a message of its channel and time");
          ++out.indexed_messages;
        }
        ck.index_end = c.pos();
        break;
      }
      case Op::DataEnd: {
        if (r.u32() != io::mcap::crc32(file.substr(0, at))) c.fail("the data section CRC");
        data_end = true;
        summary_at = c.pos();
        break;
      }
      default:
        c.fail("an unexpected record in the data section");
      }
      continue;
    }
    // The summary and its offsets.
    if (op == Op::SummaryOffset) {
      if (offsets.empty()) offsets_at = at;
      const std::uint8_t g = r.u8();
      offsets[g] = {r.u64(), r.u64()};
      continue;
    }
    if (!offsets.empty()) c.fail("a summary record after the summary offsets");
    if (!summary_records.empty() && summary_records.back().first != op)
      for (const auto& [o, _] : summary_records)
        if (o == op) c.fail("the summary is not grouped by opcode");
    summary_records.emplace_back(op, at);
    switch (op) {
    case Op::Schema:
    case Op::Channel:
      break; // duplicates of the data section's, compared below by the caller's counts
    case Op::Statistics: {
      if (statistics) c.fail("two Statistics records");
      statistics = true;
      auto& s = out.statistics;
      s.message_count = r.u64();
      s.schema_count = r.u16();
      s.channel_count = r.u32();
      s.attachment_count = r.u32();
      s.metadata_count = r.u32();
      s.chunk_count = r.u32();
      s.start = r.u64();
      s.end = r.u64();
      Cursor m(r.bytes(r.u32()), "channel message counts");
      while (!m.done()) {
        const std::uint16_t id = m.u16();
        s.channel_counts[id] = m.u64();
      }
      break;
    }
    case Op::ChunkIndex:
      chunk_index_contents.emplace_back(content);
      break;
    default:
      c.fail("an unexpected record in the summary");
    }
  }
  // Each summary group at its SummaryOffset.
  std::map<std::uint8_t, std::pair<std::uint64_t, std::uint64_t>> groups;
  for (std::size_t i = 0; i < summary_records.size(); ++i) {
    const auto g = static_cast<std::uint8_t>(summary_records[i].first);
    const std::uint64_t end =
        i + 1 < summary_records.size() ? summary_records[i + 1].second : offsets_at;
    auto [it, fresh] = groups.try_emplace(g, summary_records[i].second, 0);
    it->second.second = end - it->second.first;
    (void)fresh;
  }
  if (groups != offsets) throw std::runtime_error("the SummaryOffsets are not the groups");
  // Each ChunkIndex at its chunk.
  if (chunk_index_contents.size() != chunks.size())
    throw std::runtime_error("not one ChunkIndex per chunk");
  for (std::size_t i = 0; i < chunks.size(); ++i) {
    const auto& ck = chunks[i];
    Cursor r(chunk_index_contents[i], "chunk index " + std::to_string(i));
    if (r.u64() != ck.start || r.u64() != ck.end) r.fail("time range");
    if (r.u64() != ck.at || r.u64() != ck.length) r.fail("the chunk's offset or length");
    Cursor m(r.bytes(r.u32()), "message index offsets");
    std::map<std::uint16_t, std::uint64_t> at;
    while (!m.done()) {
      const std::uint16_t id = m.u16();
      at[id] = m.u64();
    }
    if (at != ck.index_at) r.fail("message index offsets");
    if (r.u64() != ck.index_end - (ck.at + ck.length)) r.fail("message index length");
    if (r.str() != "" || r.u64() != ck.size || r.u64() != ck.size) r.fail("sizes");
  }
  // Statistics against what was read.
  const auto& s = out.statistics;
  if (!statistics) throw std::runtime_error("no Statistics record");
  std::map<std::uint16_t, std::uint64_t> counts;
  for (const auto& [id, ch] : out.channels) counts[id] = 0;
  std::uint64_t lo = 0, hi = 0;
  for (std::size_t i = 0; i < out.messages.size(); ++i) {
    const auto t = out.messages[i].log_time;
    lo = i == 0 ? t : std::min(lo, t);
    hi = i == 0 ? t : std::max(hi, t);
    ++counts[out.messages[i].channel_id];
  }
  if (s.message_count != out.messages.size() || s.schema_count != out.schemas.size() ||
      s.channel_count != out.channels.size() || s.chunk_count != out.chunks ||
      s.attachment_count != 0 || s.metadata_count != 0 || s.start != lo || s.end != hi ||
      s.channel_counts != counts)
    throw std::runtime_error("the Statistics are not the file's");
  return out;
}

} // namespace antkit::test::mcap
