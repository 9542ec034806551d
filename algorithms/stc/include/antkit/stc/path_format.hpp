#pragma once
// A compact binary form of a tour (`antkit stc --path-out FILE.bin`, read back by `antkit check stc
// --path FILE.bin`): two bits per move, since every move of a tour is to a 4-adjacent sub-cell.
//
//   bytes 0-7    the magic "ANTKPTH1"
//   bytes 8-15   the map's width and height, uint32 little-endian each
//   bytes 16-23  the start sub-cell x and y, int32 little-endian each
//   bytes 24-31  the number of moves M (positions - 1), uint64 little-endian
//   then         ceil(M / 4) bytes: move k in bits 2 (k mod 4) and 2 (k mod 4) + 1 of byte k / 4,
//                0 east (x + 1), 1 north (y - 1), 2 west (x - 1), 3 south (y + 1) (the kernel's
//                direction order); the unused bits of the last byte are 0.
// A 16384 x 16384 map's tour takes 64 MiB this way against about 3 GiB as CSV.
#include <antkit/kernel/grid.hpp>
#include <antkit/kernel/input_error.hpp>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace antkit::stc::path_format {

inline constexpr std::string_view kMagic = "ANTKPTH1";
inline constexpr std::size_t kHeaderBytes = 32;

inline void put_le(std::string& out, std::uint64_t v, int bytes) {
  for (int b = 0; b < bytes; ++b) out += static_cast<char>((v >> (8 * b)) & 0xFF);
}

inline std::uint64_t get_le(std::string_view in, std::size_t at, int bytes) {
  std::uint64_t v = 0;
  for (int b = 0; b < bytes; ++b)
    v |= std::uint64_t{static_cast<unsigned char>(in[at + static_cast<std::size_t>(b)])} << (8 * b);
  return v;
}

// The header; `moves` may be patched later (patch_moves) when it is not known in advance.
inline std::string header(std::int32_t width, std::int32_t height, kernel::Cell start,
                          std::uint64_t moves) {
  std::string h(kMagic);
  put_le(h, static_cast<std::uint32_t>(width), 4);
  put_le(h, static_cast<std::uint32_t>(height), 4);
  put_le(h, static_cast<std::uint32_t>(start.x), 4);
  put_le(h, static_cast<std::uint32_t>(start.y), 4);
  put_le(h, moves, 8);
  return h;
}

// The code of the move from a to b, or -1 when they are not 4-adjacent.
inline int move_code(kernel::Cell a, kernel::Cell b) noexcept {
  const std::int64_t dx = std::int64_t{b.x} - a.x, dy = std::int64_t{b.y} - a.y;
  if (dy == 0 && dx == 1) return 0;
  if (dx == 0 && dy == -1) return 1;
  if (dy == 0 && dx == -1) return 2;
  if (dx == 0 && dy == 1) return 3;
  return -1;
}

// The moves of a tour as they come, packed two bits each (the command streams a tour of any length
// through it; encode() below is the whole-tour form). add() takes each position, the start first,
// and appends every completed byte to `out`; finish() appends the last, partial byte. The header
// (header(), with moves()) is the caller's: a stream writes it first and patches the count.
class Encoder {
public:
  // False (nothing appended) when `s` is not 4-adjacent to the position before it.
  bool add(kernel::Cell s, std::string& out) {
    if (have_last_) {
      const int code = move_code(last_, s);
      if (code < 0) return false;
      byte_ = static_cast<unsigned char>(byte_ | (code << (2 * (moves_ % 4))));
      if (++moves_ % 4 == 0) {
        out += static_cast<char>(byte_);
        byte_ = 0;
      }
    }
    have_last_ = true;
    last_ = s;
    return true;
  }
  void finish(std::string& out) {
    if (moves_ % 4 != 0) out += static_cast<char>(byte_);
    byte_ = 0;
  }
  [[nodiscard]] std::uint64_t moves() const noexcept { return moves_; }

private:
  std::uint64_t moves_ = 0;
  bool have_last_ = false;
  kernel::Cell last_{};
  unsigned char byte_ = 0;
};

// A whole tour (the start first) in this format: decode(encode(...)) gives it back. Throws
// kernel::InputError("path", ...) at the first move that is not to a 4-adjacent sub-cell.
inline std::string encode(std::int32_t width, std::int32_t height,
                          const std::vector<kernel::Cell>& path) {
  if (path.empty()) throw kernel::InputError("path", "an empty tour has no start");
  Encoder e;
  std::string moves;
  for (std::size_t i = 0; i < path.size(); ++i)
    if (!e.add(path[i], moves))
      throw kernel::InputError("path", "position " + std::to_string(i) +
                                           " is not 4-adjacent to the one before it");
  e.finish(moves);
  return header(width, height, path.front(), e.moves()) + moves;
}

// A tour file written as the positions come (`antkit stc --path-out`): CSV (a first line "x,y",
// then "x,y" per position) or the binary form above. finish() writes what is buffered and, for the
// binary form, the move count into the header, so the stream must be seekable (a file). add()
// throws std::logic_error for a binary move that is not 4-adjacent (a tour never makes one).
class TourWriter {
public:
  TourWriter(std::ostream& out, bool binary, std::int32_t width, std::int32_t height,
             kernel::Cell start)
      : out_(out), binary_(binary) {
    buf_ = binary_ ? header(width, height, start, 0) : std::string("x,y\n");
  }

  void add(kernel::Cell s) {
    if (binary_) {
      if (!encoder_.add(s, buf_)) throw std::logic_error("a tour move that is not 4-adjacent");
    } else {
      char digits[32];
      char* end = std::to_chars(digits, digits + 12, s.x).ptr;
      *end++ = ',';
      end = std::to_chars(end, end + 12, s.y).ptr;
      *end++ = '\n';
      buf_.append(digits, end);
    }
    if (buf_.size() >= kBuffer) flush();
  }

  void finish() {
    if (binary_) encoder_.finish(buf_);
    flush();
    if (binary_) { // the number of moves, now known
      std::string count;
      put_le(count, encoder_.moves(), 8);
      out_.seekp(24);
      out_.write(count.data(), 8);
    }
  }

private:
  static constexpr std::size_t kBuffer = std::size_t{1} << 20;
  void flush() {
    out_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
    buf_.clear();
  }
  std::ostream& out_;
  bool binary_;
  Encoder encoder_;
  std::string buf_;
};

inline bool is_binary(std::string_view text) noexcept {
  return text.substr(0, kMagic.size()) == kMagic;
}

struct Decoded {
  std::int32_t width = 0, height = 0;
  kernel::Cell start{};
  std::vector<kernel::Cell> path; // the start first
};

// Throws kernel::InputError(source, "byte N: ...") for a file that is not this format, is cut
// short, has bytes beyond its moves, or has more than max_positions positions.
inline Decoded decode(std::string_view in, const std::string& source, std::uint64_t max_positions) {
  const auto fail = [&](std::size_t byte, const std::string& what) {
    return kernel::InputError(source, "byte " + std::to_string(byte) + ": " + what);
  };
  if (!is_binary(in)) throw fail(0, "not an antkit binary path (no \"ANTKPTH1\")");
  if (in.size() < kHeaderBytes) throw fail(in.size(), "the header is cut short");
  Decoded d;
  d.width = static_cast<std::int32_t>(get_le(in, 8, 4));
  d.height = static_cast<std::int32_t>(get_le(in, 12, 4));
  d.start = {static_cast<std::int32_t>(get_le(in, 16, 4)),
             static_cast<std::int32_t>(get_le(in, 20, 4))};
  const std::uint64_t moves = get_le(in, 24, 8);
  if (moves >= max_positions)
    throw fail(24, std::to_string(moves) + " moves: more than this reader takes (" +
                       std::to_string(max_positions) + " positions)");
  const std::uint64_t bytes = (moves + 3) / 4;
  if (in.size() - kHeaderBytes != bytes)
    throw fail(in.size() < kHeaderBytes + bytes ? in.size() : kHeaderBytes + bytes,
               in.size() < kHeaderBytes + bytes
                   ? "cut short: " + std::to_string(moves) + " moves need " +
                         std::to_string(bytes) + " bytes after the header"
                   : "bytes after the last move");
  d.path.reserve(static_cast<std::size_t>(moves + 1));
  kernel::Cell at = d.start;
  d.path.push_back(at);
  constexpr std::int32_t dx[4] = {1, 0, -1, 0}, dy[4] = {0, -1, 0, 1};
  for (std::uint64_t k = 0; k < moves; ++k) {
    const int code = (static_cast<unsigned char>(in[kHeaderBytes + k / 4]) >> (2 * (k % 4))) & 3;
    const std::int64_t x = std::int64_t{at.x} + dx[code], y = std::int64_t{at.y} + dy[code];
    if (x < INT32_MIN || x > INT32_MAX || y < INT32_MIN || y > INT32_MAX)
      throw fail(kHeaderBytes + k / 4, "move " + std::to_string(k) + " leaves the int32 range");
    at = {static_cast<std::int32_t>(x), static_cast<std::int32_t>(y)};
    d.path.push_back(at);
  }
  return d;
}

} // namespace antkit::stc::path_format
