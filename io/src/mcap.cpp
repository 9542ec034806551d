// The MCAP writer (mcap.hpp), from the specification's record layouts.
#include <algorithm>
#include <antkit/io/mcap.hpp>
#include <array>
#include <limits>
#include <stdexcept>
#include <tuple>

namespace antkit::io::mcap {

namespace {

void put_map_u16_u64(std::string& out, const std::map<std::uint16_t, std::uint64_t>& m) {
  put_u32(out, static_cast<std::uint32_t>(m.size() * 10));
  for (const auto& [k, v] : m) {
    put_u16(out, k);
    put_u64(out, v);
  }
}

std::string schema_content(std::uint16_t id, std::string_view name, std::string_view encoding,
                           std::string_view data) {
  std::string c;
  put_u16(c, id);
  put_string(c, name);
  put_string(c, encoding);
  put_string(c, data); // uint32 length-prefixed bytes: the same layout as a string
  return c;
}

std::string channel_content(std::uint16_t id, std::uint16_t schema_id, std::string_view topic,
                            std::string_view encoding,
                            const std::vector<std::pair<std::string, std::string>>& metadata) {
  std::string c;
  put_u16(c, id);
  put_u16(c, schema_id);
  put_string(c, topic);
  put_string(c, encoding);
  std::string map;
  for (const auto& [k, v] : metadata) {
    put_string(map, k);
    put_string(map, v);
  }
  put_string(c, map);
  return c;
}

} // namespace

namespace {
// The n low bytes of v, little-endian, at `at`.
void store_le(char* at, std::uint64_t v, std::size_t n) noexcept {
  for (std::size_t i = 0; i < n; ++i) at[i] = static_cast<char>((v >> (8 * i)) & 0xFFU);
}
template <std::size_t N>
void put_le(std::string& out, std::uint64_t v) {
  std::array<char, N> b{};
  store_le(b.data(), v, N);
  out.append(b.data(), N);
}
} // namespace

void put_u8(std::string& out, std::uint8_t v) {
  out.push_back(static_cast<char>(v));
}
void put_u16(std::string& out, std::uint16_t v) {
  put_le<2>(out, v);
}
void put_u32(std::string& out, std::uint32_t v) {
  put_le<4>(out, v);
}
void put_u64(std::string& out, std::uint64_t v) {
  put_le<8>(out, v);
}
void put_string(std::string& out, std::string_view s) {
  if (s.size() > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("mcap: a string or byte field over 4 GiB");
  put_u32(out, static_cast<std::uint32_t>(s.size()));
  out.append(s);
}
void put_record(std::string& out, Op op, std::string_view content) {
  put_u8(out, static_cast<std::uint8_t>(op));
  put_u64(out, content.size());
  out.append(content);
}

Writer::Writer(std::ostream& out, WriterOptions options) : out_(out), options_(std::move(options)) {
  std::string head(kMagic);
  std::string c;
  put_string(c, options_.profile);
  put_string(c, options_.library);
  put_record(head, Op::Header, c);
  emit(head);
}

void Writer::emit(std::string_view bytes) {
  emit(bytes, crc32(bytes));
}

void Writer::emit(std::string_view bytes, std::uint32_t crc) {
  out_.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  position_ += bytes.size();
  data_crc_ = crc32_combine(data_crc_, crc, bytes.size());
}

std::uint16_t Writer::add_schema(std::string_view name, std::string_view encoding,
                                 std::string_view data) {
  if (finished_) throw std::logic_error("mcap: add_schema after finish");
  if (chunk_.open_) throw std::logic_error("mcap: add_schema before end_message");
  if (schemas_.size() >= 65535) throw std::logic_error("mcap: more than 65535 schemas");
  const auto id = static_cast<std::uint16_t>(schemas_.size() + 1);
  schemas_.push_back({id, std::string(name), std::string(encoding), std::string(data)});
  std::string r;
  put_record(r, Op::Schema, schema_content(id, name, encoding, data));
  emit(r);
  return id;
}

std::uint16_t
Writer::add_channel(std::uint16_t schema_id, std::string_view topic,
                    std::string_view message_encoding,
                    const std::vector<std::pair<std::string, std::string>>& metadata) {
  if (finished_) throw std::logic_error("mcap: add_channel after finish");
  if (chunk_.open_) throw std::logic_error("mcap: add_channel before end_message");
  if (schema_id > schemas_.size()) throw std::logic_error("mcap: a channel of an unknown schema");
  if (channels_.size() >= 65535) throw std::logic_error("mcap: more than 65535 channels");
  const auto id = static_cast<std::uint16_t>(channels_.size() + 1);
  channels_.push_back({id, schema_id, std::string(topic), std::string(message_encoding), metadata});
  channel_counts_[id] = 0;
  std::string r;
  put_record(r, Op::Channel, channel_content(id, schema_id, topic, message_encoding, metadata));
  emit(r);
  return id;
}

// ---- Chunk ----

std::string& Chunk::begin_message(std::uint16_t channel_id, std::uint32_t sequence,
                                  std::uint64_t log_time, std::uint64_t publish_time) {
  if (open_) throw std::logic_error("mcap: begin_message before end_message");
  if (sealed_) throw std::logic_error("mcap: a message added to a sealed chunk");
  if (channel_id == 0) throw std::logic_error("mcap: a message on channel 0");
  if (messages_ == 0) start_ = end_ = log_time;
  start_ = std::min(start_, log_time);
  end_ = std::max(end_, log_time);
  if (channel_id >= index_.size()) index_.resize(std::size_t{channel_id} + 1);
  index_[channel_id].emplace_back(log_time, records_.size());
  // The Message record's head, its length set by end_message(): opcode, length, channel,
  // sequence, log time, publish time.
  message_start_ = records_.size();
  std::array<char, 31> head{};
  head[0] = static_cast<char>(Op::Message);
  store_le(head.data() + 9, channel_id, 2);
  store_le(head.data() + 11, sequence, 4);
  store_le(head.data() + 15, log_time, 8);
  store_le(head.data() + 23, publish_time, 8);
  records_.append(head.data(), head.size());
  ++messages_;
  open_ = true;
  return records_;
}

void Chunk::end_message() {
  if (!open_) throw std::logic_error("mcap: end_message without begin_message");
  open_ = false;
  store_le(records_.data() + message_start_ + 1, records_.size() - message_start_ - 9, 8);
}

void Chunk::add(const Message& m) {
  begin_message(m.channel_id, m.sequence, m.log_time, m.publish_time).append(m.data);
  end_message();
}

void Chunk::seal() {
  if (open_) throw std::logic_error("mcap: seal before end_message");
  if (sealed_) return;
  index_records_.clear();
  index_at_.clear();
  // One MessageIndex per channel, in channel id order; entries in log time order (stable: equal
  // times keep the order they were written in; a run's times seldom go back, so mostly no sort).
  for (std::size_t channel = 1; channel < index_.size(); ++channel) {
    auto& entries = index_[channel];
    if (entries.empty()) continue;
    const auto by_time = [](const auto& a, const auto& b) { return a.first < b.first; };
    if (!std::is_sorted(entries.begin(), entries.end(), by_time))
      std::stable_sort(entries.begin(), entries.end(), by_time);
    index_at_.emplace_back(static_cast<std::uint16_t>(channel), index_records_.size());
    const std::uint64_t length = 2 + 4 + entries.size() * 16;
    put_u8(index_records_, static_cast<std::uint8_t>(Op::MessageIndex));
    put_u64(index_records_, length);
    put_u16(index_records_, static_cast<std::uint16_t>(channel));
    put_u32(index_records_, static_cast<std::uint32_t>(entries.size() * 16));
    const std::size_t at = index_records_.size();
    index_records_.resize(at + entries.size() * 16);
    char* o = index_records_.data() + at;
    for (const auto& [t, offset] : entries) {
      store_le(o, t, 8);
      store_le(o + 8, offset, 8);
      o += 16;
    }
  }
  crc_ = crc32(records_);
  sealed_ = true;
}

void Chunk::clear() noexcept {
  records_.clear();
  open_ = sealed_ = false;
  start_ = end_ = messages_ = 0;
  for (auto& entries : index_) entries.clear();
  crc_ = 0;
  index_records_.clear();
  index_at_.clear();
}

// ---- Writer ----

void Writer::write(const Message& m) {
  begin_message(m.channel_id, m.sequence, m.log_time, m.publish_time).append(m.data);
  end_message();
}

std::string& Writer::begin_message(std::uint16_t channel_id, std::uint32_t sequence,
                                   std::uint64_t log_time, std::uint64_t publish_time) {
  if (finished_) throw std::logic_error("mcap: write after finish");
  if (channel_id == 0 || channel_id > channels_.size())
    throw std::logic_error("mcap: a message on an unknown channel");
  return chunk_.begin_message(channel_id, sequence, log_time, publish_time);
}

void Writer::end_message() {
  chunk_.end_message();
  if (chunk_.size() >= options_.chunk_size) emit_chunk(chunk_);
}

void Writer::check_channels(const Chunk& chunk) const {
  if (chunk.open_) throw std::logic_error("mcap: a chunk written before its end_message");
  for (std::size_t channel = channels_.size() + 1; channel < chunk.index_.size(); ++channel)
    if (!chunk.index_[channel].empty())
      throw std::logic_error("mcap: a message on an unknown channel");
}

void Writer::write_chunk(Chunk& chunk) {
  if (finished_) throw std::logic_error("mcap: write after finish");
  if (chunk_.open_) throw std::logic_error("mcap: write_chunk before end_message");
  check_channels(chunk);
  emit_chunk(chunk_); // the open chunk first
  emit_chunk(chunk);
}

void Writer::emit_chunk(Chunk& c) {
  if (c.empty()) {
    c.clear();
    return;
  }
  c.seal();
  const std::uint64_t chunk_offset = position_;
  const std::uint64_t size = c.records_.size();
  // The record's head, then its records as they are (no copy of the chunk).
  std::string head;
  put_u8(head, static_cast<std::uint8_t>(Op::Chunk));
  put_u64(head, 8 + 8 + 8 + 4 + 4 + 8 + size);
  put_u64(head, c.start_);
  put_u64(head, c.end_);
  put_u64(head, size);
  put_u32(head, c.crc_);
  put_string(head, ""); // no compression
  put_u64(head, size);
  emit(head);
  emit(c.records_, c.crc_); // the records' CRC serves the data section's too
  const std::uint64_t chunk_length = head.size() + size;
  const std::uint64_t index_start = position_;
  emit(c.index_records_);
  std::map<std::uint16_t, std::uint64_t> index_offsets;
  for (const auto& [channel, at] : c.index_at_) {
    index_offsets[channel] = index_start + at;
    channel_counts_[channel] += c.index_[channel].size();
  }
  std::string ci;
  put_u64(ci, c.start_);
  put_u64(ci, c.end_);
  put_u64(ci, chunk_offset);
  put_u64(ci, chunk_length);
  put_map_u16_u64(ci, index_offsets);
  put_u64(ci, c.index_records_.size());
  put_string(ci, "");
  put_u64(ci, size); // compressed size: the records as they are
  put_u64(ci, size);
  put_record(chunk_indexes_, Op::ChunkIndex, ci);
  start_time_ = message_count_ == 0 ? c.start_ : std::min(start_time_, c.start_);
  end_time_ = message_count_ == 0 ? c.end_ : std::max(end_time_, c.end_);
  message_count_ += c.messages_;
  ++chunk_count_;
  c.clear();
}

std::vector<std::pair<std::string, std::uint64_t>> Writer::channel_counts() const {
  std::vector<std::pair<std::string, std::uint64_t>> out;
  for (const auto& c : channels_) {
    const std::uint64_t open = c.id < chunk_.index_.size() ? chunk_.index_[c.id].size() : 0;
    out.emplace_back(c.topic, channel_counts_.at(c.id) + open);
  }
  return out;
}

void Writer::finish() {
  if (finished_) throw std::logic_error("mcap: finish twice");
  if (chunk_.open_) throw std::logic_error("mcap: finish before end_message");
  emit_chunk(chunk_);
  std::string end;
  std::string dc;
  put_u32(dc, data_crc_);
  put_record(end, Op::DataEnd, dc);
  emit(end);
  finished_ = true;

  // The summary, grouped by opcode; each group's offset and length for its SummaryOffset.
  const std::uint64_t summary_start = position_;
  std::string summary;
  std::vector<std::tuple<Op, std::uint64_t, std::uint64_t>> groups;
  const auto group = [&](Op op, const std::string& records) {
    if (records.empty()) return;
    groups.emplace_back(op, summary_start + summary.size(), records.size());
    summary += records;
  };
  std::string schemas, channels, statistics;
  for (const auto& s : schemas_)
    put_record(schemas, Op::Schema, schema_content(s.id, s.name, s.encoding, s.data));
  for (const auto& c : channels_)
    put_record(channels, Op::Channel,
               channel_content(c.id, c.schema_id, c.topic, c.encoding, c.metadata));
  std::string st;
  put_u64(st, message_count_);
  put_u16(st, static_cast<std::uint16_t>(schemas_.size()));
  put_u32(st, static_cast<std::uint32_t>(channels_.size()));
  put_u32(st, 0); // attachments
  put_u32(st, 0); // metadata
  put_u32(st, chunk_count_);
  put_u64(st, start_time_);
  put_u64(st, end_time_);
  put_map_u16_u64(st, channel_counts_);
  put_record(statistics, Op::Statistics, st);
  group(Op::Schema, schemas);
  group(Op::Channel, channels);
  group(Op::Statistics, statistics);
  group(Op::ChunkIndex, chunk_indexes_);

  const std::uint64_t offsets_start = summary_start + summary.size();
  std::string offsets;
  for (const auto& [op, start, length] : groups) {
    std::string oc;
    put_u8(oc, static_cast<std::uint8_t>(op));
    put_u64(oc, start);
    put_u64(oc, length);
    put_record(offsets, Op::SummaryOffset, oc);
  }
  // The footer: its CRC covers the summary, the offsets and the footer up to this field.
  std::string tail = summary + offsets;
  put_u8(tail, static_cast<std::uint8_t>(Op::Footer));
  put_u64(tail, 8 + 8 + 4);
  put_u64(tail, summary_start);
  put_u64(tail, offsets_start);
  put_u32(tail, crc32(tail));
  tail.append(kMagic);
  emit(tail);
  out_.flush();
}

} // namespace antkit::io::mcap
