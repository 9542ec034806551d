// The MCAP reader (mcap_reader.hpp), from the specification's Records and Serialization sections.
#include <antkit/io/crc32.hpp>
#include <antkit/io/mcap_reader.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cstring>
#include <fcntl.h>
#include <lz4frame.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zstd.h>

namespace antkit::io::mcap {

namespace {

constexpr std::string_view kMagic{"\x89MCAP0\r\n", 8};
constexpr std::uint8_t kHeader = 0x01, kFooter = 0x02, kSchema = 0x03, kChannel = 0x04,
                       kMessage = 0x05, kChunk = 0x06, kDataEnd = 0x0F;
constexpr std::uint64_t kRecordHead = 9;               // opcode, uint64 length
constexpr std::uint64_t kFooterRecord = 9 + 8 + 8 + 4; // opcode, length, two offsets, a CRC
// A chunk larger than this uncompressed is refused rather than allocated (rosbag2 writes chunks of
// a few MiB; the limit stops a 20-byte file from asking for terabytes).
constexpr std::uint64_t kMaxChunk = std::uint64_t{1} << 30;

// Fields of one record's content, each read with its bounds checked; `base` is the content's
// offset for errors (in the file, or in a chunk's records).
struct Fields {
  std::string_view s;
  std::uint64_t base = 0;
  std::size_t at = 0;
  const char* error = nullptr;

  bool need(std::size_t n) {
    if (s.size() - at < n) {
      if (error == nullptr) error = "a field runs past the end of its record";
      return false;
    }
    return true;
  }
  template <class T>
  T le() {
    if (!need(sizeof(T))) return 0;
    T v = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i)
      v |= static_cast<T>(static_cast<T>(static_cast<unsigned char>(s[at + i])) << (8 * i));
    at += sizeof(T);
    return v;
  }
  std::string_view bytes(std::uint64_t n) {
    if (!need(n > s.size() ? s.size() + 1 : static_cast<std::size_t>(n))) return {};
    const auto v = s.substr(at, static_cast<std::size_t>(n));
    at += static_cast<std::size_t>(n);
    return v;
  }
  std::string_view str() { return bytes(le<std::uint32_t>()); }
  std::string_view rest() { return bytes(s.size() - at); }
};

} // namespace

struct Reader::Mapping {
  void* base = nullptr;
  std::size_t size = 0;
  ~Mapping() {
    if (base != nullptr) ::munmap(base, size);
  }
};

Reader::Reader(const std::string& path, ReaderOptions options)
    : mapping_(std::make_unique<Mapping>()), name_(path), options_(options) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw kernel::InputError(path, std::string("cannot open: ") + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw kernel::InputError(path, "not a regular file");
  }
  if (st.st_size > 0) {
    void* m = ::mmap(nullptr, static_cast<std::size_t>(st.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
    if (m == MAP_FAILED) {
      ::close(fd);
      throw kernel::InputError(path, std::string("cannot map: ") + std::strerror(errno));
    }
    ::madvise(m, static_cast<std::size_t>(st.st_size), MADV_SEQUENTIAL);
    mapping_->base = m;
    mapping_->size = static_cast<std::size_t>(st.st_size);
    file_ = {static_cast<const char*>(m), mapping_->size};
  }
  ::close(fd);
  open();
}

Reader::Reader(std::string_view bytes, std::string name, ReaderOptions options)
    : file_(bytes), name_(std::move(name)), options_(options) {
  open();
}

Reader::~Reader() = default;

void Reader::fail(std::uint64_t offset, const std::string& what) const {
  throw kernel::InputError(name_ + ": byte " + std::to_string(offset), what);
}

void Reader::open() {
  const std::uint64_t size = file_.size();
  if (size < kMagic.size() || file_.substr(0, kMagic.size()) != kMagic)
    fail(0, "not an MCAP file (expected the magic bytes 0x89 'MCAP0' CR LF)");
  if (size < 2 * kMagic.size() + kFooterRecord + kRecordHead ||
      file_.substr(size - kMagic.size()) != kMagic)
    fail(size, "truncated MCAP file (expected a Footer record and the closing magic bytes)");
  // The Header, first.
  std::uint64_t at = kMagic.size();
  if (static_cast<std::uint8_t>(file_[at]) != kHeader) fail(at, "expected a Header record");
  Fields head{file_.substr(at + 1, 8), at + 1};
  const std::uint64_t length = head.le<std::uint64_t>();
  if (length > size - at - kRecordHead) fail(at, "the Header record's length runs past the file");
  Fields header{file_.substr(at + kRecordHead, length), at + kRecordHead};
  profile_ = header.str();
  library_ = header.str();
  if (header.error != nullptr) fail(at, std::string("Header record: ") + header.error);
  pos_ = at + kRecordHead + length;
  // The Footer, last: where the summary starts, and its CRC.
  const std::uint64_t footer = size - kMagic.size() - kFooterRecord;
  if (static_cast<std::uint8_t>(file_[footer]) != kFooter)
    fail(footer, "expected the Footer record before the closing magic bytes");
  Fields f{file_.substr(footer + 1, kFooterRecord - 1), footer + 1};
  if (f.le<std::uint64_t>() != kFooterRecord - kRecordHead)
    fail(footer, "the Footer record's length is not 20");
  const std::uint64_t summary_start = f.le<std::uint64_t>();
  f.le<std::uint64_t>(); // summary_offset_start: the summary is not used (the data is read in
                         // order)
  const std::uint32_t summary_crc = f.le<std::uint32_t>();
  if (summary_start != 0 && (summary_start < pos_ || summary_start > footer))
    fail(footer + kRecordHead, "the Footer's summary start is outside the file");
  data_end_ = summary_start != 0 ? summary_start : footer;
  if (options_.check_crcs && summary_crc != 0 && summary_start != 0) {
    const auto crc = crc32(file_.substr(summary_start, footer + kRecordHead + 16 - summary_start));
    if (crc != summary_crc) fail(footer, "the summary's CRC does not match the Footer's");
  }
}

const SchemaInfo* Reader::schema_of(const ChannelInfo& channel) const {
  const auto it = schemas_.find(channel.schema_id);
  return it == schemas_.end() ? nullptr : &it->second;
}

std::string Reader::where(const MessageView& m) const {
  if (!m.in_chunk) return name_ + ": byte " + std::to_string(m.offset);
  return name_ + ": byte " + std::to_string(m.chunk_offset) + " (chunk), record byte " +
         std::to_string(m.offset);
}

void Reader::on_schema(std::string_view content, std::uint64_t offset) {
  Fields r{content, offset};
  SchemaInfo s;
  s.id = r.le<std::uint16_t>();
  s.name = r.str();
  s.encoding = r.str();
  s.data = r.str();
  if (r.error != nullptr) fail(offset, std::string("Schema record: ") + r.error);
  if (s.id == 0) fail(offset, "Schema record: id 0 is reserved");
  schemas_[s.id] = std::move(s);
}

void Reader::on_channel(std::string_view content, std::uint64_t offset) {
  Fields r{content, offset};
  ChannelInfo c;
  c.id = r.le<std::uint16_t>();
  c.schema_id = r.le<std::uint16_t>();
  c.topic = r.str();
  c.message_encoding = r.str();
  Fields map{r.bytes(r.le<std::uint32_t>()), offset};
  while (r.error == nullptr && map.error == nullptr && map.at < map.s.size()) {
    std::string key(map.str());
    std::string value(map.str());
    c.metadata.emplace_back(std::move(key), std::move(value));
  }
  if (r.error != nullptr || map.error != nullptr)
    fail(offset, std::string("Channel record: ") + (r.error != nullptr ? r.error : map.error));
  if (c.schema_id != 0 && !schemas_.contains(c.schema_id))
    fail(offset, "Channel record: topic '" + c.topic + "' names schema " +
                     std::to_string(c.schema_id) + ", which no Schema record before it defines");
  channels_[c.id] = std::move(c);
}

void Reader::open_chunk(std::string_view content, std::uint64_t offset) {
  Fields r{content, offset};
  r.le<std::uint64_t>(); // message_start_time
  r.le<std::uint64_t>(); // message_end_time
  const std::uint64_t size = r.le<std::uint64_t>();
  const std::uint32_t crc = r.le<std::uint32_t>();
  const std::string_view compression = r.str();
  const std::uint64_t records_length = r.le<std::uint64_t>();
  if (r.error != nullptr) fail(offset, std::string("Chunk record: ") + r.error);
  const std::string_view records = r.rest();
  if (records_length != records.size())
    fail(offset, "Chunk record: its records' length (" + std::to_string(records_length) +
                     ") is not the rest of the record (" + std::to_string(records.size()) + ")");
  if (size > kMaxChunk)
    fail(offset, "Chunk record: " + std::to_string(size) + " bytes uncompressed (at most " +
                     std::to_string(kMaxChunk) + " are read)");
  const auto buffer = [&]() -> char* {
    if (buffer_size_ < size || !buffer_) {
      buffer_ = std::make_unique_for_overwrite<char[]>(size == 0 ? 1 : size);
      buffer_size_ = size;
    }
    return buffer_.get();
  };
  if (compression.empty()) {
    if (records.size() != size)
      fail(offset, "Chunk record: uncompressed size " + std::to_string(size) + " but " +
                       std::to_string(records.size()) + " bytes of records");
    chunk_ = records;
  } else if (compression == "zstd") {
    char* out = buffer();
    const std::size_t n = ZSTD_decompress(out, size, records.data(), records.size());
    if (ZSTD_isError(n) != 0U)
      fail(offset, std::string("Chunk record: zstd: ") + ZSTD_getErrorName(n));
    if (n != size)
      fail(offset, "Chunk record: zstd gave " + std::to_string(n) + " bytes, the chunk says " +
                       std::to_string(size));
    chunk_ = {out, size};
  } else if (compression == "lz4") {
    char* out = buffer();
    LZ4F_dctx* ctx = nullptr;
    if (LZ4F_isError(LZ4F_createDecompressionContext(&ctx, LZ4F_VERSION)) != 0U)
      fail(offset, "Chunk record: lz4: cannot create a decompression context");
    std::size_t in_at = 0, out_at = 0, hint = 1;
    while (hint != 0 && in_at < records.size()) {
      std::size_t out_n = size - out_at, in_n = records.size() - in_at;
      hint = LZ4F_decompress(ctx, out + out_at, &out_n, records.data() + in_at, &in_n, nullptr);
      if (LZ4F_isError(hint) != 0U) {
        const std::string error = LZ4F_getErrorName(hint);
        LZ4F_freeDecompressionContext(ctx);
        fail(offset, "Chunk record: lz4: " + error);
      }
      if (in_n == 0 && out_n == 0) break; // no progress: the output is full
      in_at += in_n, out_at += out_n;
    }
    LZ4F_freeDecompressionContext(ctx);
    if (hint != 0 || out_at != size)
      fail(offset, "Chunk record: lz4 gave " + std::to_string(out_at) +
                       " bytes of a whole frame, the chunk says " + std::to_string(size));
    chunk_ = {out, size};
  } else {
    fail(offset, "Chunk record: unknown compression '" + std::string(compression) +
                     "' (expected '', 'zstd' or 'lz4')");
  }
  if (options_.check_crcs) {
    const std::uint32_t records_crc = crc != 0 || compression.empty() ? crc32(chunk_) : 0;
    if (crc != 0 && records_crc != crc)
      fail(offset, "Chunk record: the CRC of its uncompressed records does not match");
    if (compression.empty()) {
      // The data section's CRC over these bytes, from their CRC (one pass over them, not two).
      const auto begin = static_cast<std::uint64_t>(records.data() - file_.data());
      data_crc_ = crc32(file_.substr(crc_pos_, begin - crc_pos_), data_crc_);
      data_crc_ = crc32_combine(data_crc_, records_crc, records.size());
      crc_pos_ = begin + records.size();
    }
  }
  chunk_pos_ = 0;
  chunk_offset_ = offset;
  in_chunk_ = true;
}

bool Reader::next(MessageView& out) {
  for (;;) {
    if (in_chunk_) {
      if (chunk_pos_ == chunk_.size()) {
        in_chunk_ = false;
        continue;
      }
      const std::uint64_t at = chunk_pos_;
      if (chunk_.size() - at < kRecordHead)
        fail(chunk_offset_, "Chunk record: a record at byte " + std::to_string(at) +
                                " of its records is cut short");
      const auto op = static_cast<std::uint8_t>(chunk_[at]);
      Fields head{chunk_.substr(at + 1, 8), at};
      const std::uint64_t length = head.le<std::uint64_t>();
      if (length > chunk_.size() - at - kRecordHead)
        fail(chunk_offset_, "Chunk record: the length of the record at byte " + std::to_string(at) +
                                " of its records runs past the chunk");
      const std::string_view content = chunk_.substr(at + kRecordHead, length);
      chunk_pos_ = at + kRecordHead + length;
      if (op == kMessage) {
        Fields r{content, at};
        const auto channel = r.le<std::uint16_t>();
        out.sequence = r.le<std::uint32_t>();
        out.log_time = r.le<std::uint64_t>();
        out.publish_time = r.le<std::uint64_t>();
        if (r.error != nullptr)
          fail(chunk_offset_, "Message record at byte " + std::to_string(at) +
                                  " of the chunk's records: " + r.error);
        const auto it = channels_.find(channel);
        if (it == channels_.end())
          fail(chunk_offset_, "Message record at byte " + std::to_string(at) +
                                  " of the chunk's records: channel " + std::to_string(channel) +
                                  " is not defined before it");
        out.channel = &it->second;
        out.data = content.substr(22);
        out.offset = at;
        out.in_chunk = true;
        out.chunk_offset = chunk_offset_;
        return true;
      }
      if (op == kSchema) on_schema(content, chunk_offset_);
      if (op == kChannel) on_channel(content, chunk_offset_);
      continue; // other records inside a chunk are not the spec's; skipped as unknown
    }
    if (done_) return false;
    const std::uint64_t at = pos_;
    if (at >= data_end_) {
      done_ = true;
      return false;
    }
    if (data_end_ - at < kRecordHead) fail(at, "a record is cut short (truncated file?)");
    const auto op = static_cast<std::uint8_t>(file_[at]);
    Fields head{file_.substr(at + 1, 8), at + 1};
    const std::uint64_t length = head.le<std::uint64_t>();
    if (length > data_end_ - at - kRecordHead)
      fail(at, "the record's length (" + std::to_string(length) +
                   " bytes) runs past the end of the data section (truncated file?)");
    const std::string_view content = file_.substr(at + kRecordHead, length);
    pos_ = at + kRecordHead + length;
    switch (op) {
    case kSchema:
      on_schema(content, at);
      break;
    case kChannel:
      on_channel(content, at);
      break;
    case kChunk:
      open_chunk(content, at);
      break;
    case kMessage: {
      Fields r{content, at};
      const auto channel = r.le<std::uint16_t>();
      out.sequence = r.le<std::uint32_t>();
      out.log_time = r.le<std::uint64_t>();
      out.publish_time = r.le<std::uint64_t>();
      if (r.error != nullptr) fail(at, std::string("Message record: ") + r.error);
      const auto it = channels_.find(channel);
      if (it == channels_.end())
        fail(at,
             "Message record: channel " + std::to_string(channel) + " is not defined before it");
      out.channel = &it->second;
      out.data = content.substr(22);
      out.offset = at;
      out.in_chunk = false;
      out.chunk_offset = 0;
      return true;
    }
    case kDataEnd: {
      Fields r{content, at};
      const std::uint32_t crc = r.le<std::uint32_t>();
      if (r.error != nullptr) fail(at, std::string("DataEnd record: ") + r.error);
      if (options_.check_crcs && crc != 0 &&
          crc32(file_.substr(crc_pos_, at - crc_pos_), data_crc_) != crc)
        fail(at, "the data section's CRC (DataEnd record) does not match");
      done_ = true;
      return false;
    }
    case kHeader:
      fail(at, "a second Header record");
    case kFooter:
      done_ = true;
      return false;
    default:
      break; // message indexes, attachments, metadata, unknown opcodes: not needed here
    }
  }
}

} // namespace antkit::io::mcap
