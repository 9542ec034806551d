// The Coq decision table's digest over the ant-like STC decision's input domain (issue 41), the
// value the Cortex-M4 image's `decide` mode (mcu/src/decide_run.cpp) must print.
//
//   proof_tie_ant_decide_digest GOLDEN [--first N] [--count N]
//     GOLDEN is proofs/golden/AntDecide.out (AntDecide.v's `decide`, tabulated by coqc). Prints
//     {"first": N, "inputs": COUNT, "bytes": B, "digest": "HEX"}: kernel::TraceHash (seed 0) over,
//     for each input of [N, N + COUNT) (default: the whole domain, 134 217 728 inputs) in
//     ant_stc_tie.cpp's order, the four bytes the table says ant_decide gives: move (0 E, 1 N,
//     2 W, 3 S, 4 Stop), mark (0 or 1), the quadrant and done after the step.
//
// Input n = (((quadrant * 2 + done) * 16 + free) * 16 + here) * 65536 + nb0 + 16 nb1 + 256 nb2 +
// 4096 nb3, the numbering of ant_stc_tie.cpp's loops and of its --flip-code K. The answer comes
// from the table alone, never from the shipped code: with done set, Stop with done and the
// quadrant unchanged (AntDecide.v's decide_done); otherwise the table's entry at the index the
// tie reduces each input to (ant_decide_table.hpp: the reduction decide_reads_the_view and
// decide_view_ext prove `decide` reads its input through): '.' is Stop (quadrant unchanged, done
// set), Go m q is move m, marked, quadrant q, done clear.
#include "ant_decide_table.hpp"

#include <antkit/kernel/hash.hpp>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using namespace antkit::proofs;

constexpr std::uint64_t kInputs = 4ull * 2 * (1ull << 24);

int usage() {
  std::fprintf(stderr, "usage: proof_tie_ant_decide_digest GOLDEN [--first N] [--count N]\n");
  return 2;
}

} // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc % 2 != 0) return usage();
  const std::string golden = argv[1];
  std::uint64_t first = 0, count = kInputs;
  bool counted = false;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string opt = argv[i];
    char* end = nullptr;
    const unsigned long long v = std::strtoull(argv[i + 1], &end, 10);
    if (*end != '\0' || argv[i + 1][0] < '0' || argv[i + 1][0] > '9') return usage();
    if (opt == "--first")
      first = v;
    else if (opt == "--count")
      count = v, counted = true;
    else
      return usage();
  }
  if (first > kInputs) return usage();
  if (!counted) count = kInputs - first;
  if (count > kInputs - first) {
    std::fprintf(stderr, "error: --first + --count exceeds the domain's %llu inputs\n",
                 static_cast<unsigned long long>(kInputs));
    return 2;
  }
  const auto table = read_table(golden);
  if (!table) {
    std::fprintf(stderr, "error: %s: expected four strings of 8192 entries (Compute table ...)\n",
                 golden.c_str());
    return 2;
  }
  antkit::kernel::TraceHash hash;
  for (std::uint64_t n = first; n < first + count; ++n) {
    const int cur = static_cast<int>(n >> 25);
    const bool done = ((n >> 24) & 1) != 0;
    const int free = static_cast<int>((n >> 20) & 15);
    const int here = static_cast<int>((n >> 16) & 15);
    const std::array<std::uint8_t, 4> nb{
        static_cast<std::uint8_t>(n & 15), static_cast<std::uint8_t>((n >> 4) & 15),
        static_cast<std::uint8_t>((n >> 8) & 15), static_cast<std::uint8_t>((n >> 12) & 15)};
    const Expected want =
        done ? Expected{}
             : decode((*table)[static_cast<std::size_t>(cur)][table_index(here, free, nb, cur)]);
    // move, mark, quadrant, done (Stop: antkit_stc_command's ANTKIT_STOP = 4, no mark).
    hash.add_u8(static_cast<std::uint8_t>(want.stop ? 4 : want.move))
        .add_u8(want.stop ? 0 : 1)
        .add_u8(static_cast<std::uint8_t>(want.stop ? cur : want.q))
        .add_u8(want.stop ? 1 : 0);
  }
  std::printf("{\"first\": %llu, \"inputs\": %llu, \"bytes\": %llu, \"digest\": \"%s\"}\n",
              static_cast<unsigned long long>(first), static_cast<unsigned long long>(count),
              static_cast<unsigned long long>(hash.bytes()),
              antkit::kernel::hash_hex(hash.finish()).c_str());
  return 0;
}
