// The ant-like STC decision on the robot's own processor, over its whole input domain (issue 41:
// "verified means the shipped code"). proofs/tie/ant_stc_tie.cpp holds the host's compilation of
// stc::ant_decide to the Coq table on every input; this runs the chip's compilation, through the
// C API a firmware calls (antkit_ant_stc_step, c/src/antkit.cpp, ant_decide inlined in it), on
// the same inputs in the same order, and prints a digest of every answer, which
// proofs/tie/ant_decide_digest.cpp computes from the Coq table (ctest
// proof.tie.ant_decide.cortex_m4).
//
//   semihosting command line: antkit_mcu decide FIRST COUNT [FLIP]
//
// Input n (0 <= n < 134 217 728), ant_stc_tie.cpp's numbering (its --flip-code K):
//   n = (((quadrant * 2 + done) * 16 + free) * 16 + here) * 65536 + nb0 + 16 nb1 + 256 nb2 + 4096
//   nb3
// The chip's state for (quadrant, done) is made through the C API: antkit_ant_stc_init(quadrant),
// and for done = 1 one more step that closes the tour (nothing free, all four sub-cells covered:
// decide says Stop and sets done). Each input is one antkit_ant_stc_step from a copy of that state
// with the reading {free, here, nb0..nb3}.
//
// The digest: kernel::TraceHash (seed 0) over, for each input of [FIRST, FIRST + COUNT) in order,
// four bytes: the command's move (0 E, 1 N, 2 W, 3 S, 4 Stop) and mark (0 or 1), then the state's
// quadrant and done after the step. The C API keeps the state as AntStc's two bytes (c/src/
// antkit.cpp stores the object with memcpy): byte 0 the quadrant, byte 1 done. The digest reads
// those bytes, which are what the robot's next step starts from; a change of that layout makes the
// digest differ (a failure, never a false pass).
//
// FLIP: the tooth. On input FLIP the chip's command is replaced as ant_stc_tie.cpp's --flip-code
// does (Stop becomes a marked move east, any move becomes Stop), so the digest must differ.
#include "decide_run.hpp"

#include "semihost.hpp"
#include "text.hpp"
#include "ticks.hpp"

#include <antkit/c/antkit.h>
#include <antkit/kernel/hash.hpp>

namespace antkit::mcu {

namespace {

// A decimal number up to 2^32 - 1 at *s, advancing s past it and the spaces after it.
bool parse_u32(const char*& s, std::uint32_t& out) {
  if (*s < '0' || *s > '9') return false;
  std::uint64_t v = 0;
  while (*s >= '0' && *s <= '9') {
    v = v * 10 + static_cast<std::uint64_t>(*s++ - '0');
    if (v > 0xFFFFFFFFu) return false;
  }
  if (*s != 0 && *s != ' ') return false;
  while (*s == ' ') ++s;
  out = static_cast<std::uint32_t>(v);
  return true;
}

// The four bytes of one answer, little-endian as TraceHash::add_u32 appends them: move, mark,
// quadrant, done.
inline std::uint32_t answer(antkit_stc_command c, const antkit_ant_stc& s) {
  return std::uint32_t{c.move} | std::uint32_t{c.mark} << 8 | std::uint32_t{s.opaque[0]} << 16 |
         std::uint32_t{s.opaque[1]} << 24;
}

// The enumeration (kept out of line so that the map file shows its size). Two answers are appended
// as one 8-byte word (the same stream as two add_u32 calls: TraceHash's definition), which spares
// the chip half of the hash's per-byte bookkeeping.
[[gnu::noinline]] std::uint64_t enumerate(std::uint32_t first, std::uint32_t count,
                                          std::int64_t flip, std::uint64_t& bytes) {
  // The eight states, made through the C API.
  antkit_ant_stc states[4][2];
  for (int q = 0; q < 4; ++q) {
    antkit_ant_stc_init(&states[q][0], q);
    states[q][1] = states[q][0];
    const antkit_mark_reading closing{0, 15, {0, 0, 0, 0}};
    antkit_ant_stc_step(&states[q][1], &closing);
  }
  kernel::TraceHash hash;
  std::uint32_t pending = 0;
  bool odd = false;
  const std::uint32_t end = first + count;
  for (std::uint32_t n = first; n != end; ++n) {
    const std::uint32_t nbs = n & 0xFFFF;
    antkit_mark_reading r{
        static_cast<std::uint8_t>((n >> 20) & 15),
        static_cast<std::uint8_t>((n >> 16) & 15),
        {static_cast<std::uint8_t>(nbs & 15), static_cast<std::uint8_t>(nbs >> 4 & 15),
         static_cast<std::uint8_t>(nbs >> 8 & 15), static_cast<std::uint8_t>(nbs >> 12)}};
    antkit_ant_stc s = states[n >> 25][(n >> 24) & 1];
    antkit_stc_command c = antkit_ant_stc_step(&s, &r);
    if (static_cast<std::int64_t>(n) == flip)
      c = c.move == ANTKIT_STOP ? antkit_stc_command{ANTKIT_EAST, 1}
                                : antkit_stc_command{ANTKIT_STOP, 0};
    const std::uint32_t a = answer(c, s);
    if (odd)
      hash.add_u64(std::uint64_t{pending} | std::uint64_t{a} << 32);
    else
      pending = a;
    odd = !odd;
  }
  if (odd) hash.add_u32(pending);
  bytes = hash.bytes();
  return hash.finish();
}

} // namespace

int run_decide(const char* args) {
  std::uint32_t first = 0, count = 0, flip_arg = 0;
  if (!parse_u32(args, first) || !parse_u32(args, count))
    return refuse("decide", "expected FIRST COUNT [FLIP] (decimal input numbers)");
  std::int64_t flip = -1;
  if (*args != 0) {
    if (!parse_u32(args, flip_arg) || *args != 0)
      return refuse("decide", "expected FIRST COUNT [FLIP] (decimal input numbers)");
    flip = flip_arg;
  }
  if (first > kDecideInputs || count > kDecideInputs - first)
    return refuse("decide", "FIRST + COUNT exceeds the domain's 134217728 inputs");
  ticks_start();
  std::uint64_t bytes = 0;
  const std::uint64_t digest = enumerate(first, count, flip, bytes);
  const std::uint64_t ticks = ticks_now();
  Text t;
  t << "{\"decide\": \"antkit_ant_stc_step\", \"first\": " << std::int64_t{first}
    << ", \"inputs\": " << std::int64_t{count} << ", \"bytes\": ";
  t.u64(bytes) << ", \"digest\": \"";
  t.hex(digest) << "\", \"flip\": " << flip << ", \"ticks\": " << static_cast<std::int64_t>(ticks)
                << "}\n";
  t.flush();
  return 0;
}

} // namespace antkit::mcu
