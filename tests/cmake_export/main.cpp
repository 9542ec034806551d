// Uses each installed layer once and checks an answer, so that a broken package fails here.
#include <antkit/algorithms/controller.hpp>
#include <antkit/kernel/grid.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/random.hpp>
#include <cstdio>

int main() {
  antkit::kernel::Grid<std::uint8_t> grid(4, 3, 0);
  grid[{1, 2}] = 7;
  antkit::kernel::Stream stream(1, 2, 3, 4, 5);
  const auto draw = stream.below(10);
  antkit::kernel::TraceHash hash;
  hash.add_u32(draw).add_u8(grid[{1, 2}]);
  const bool ok = grid.size() == 12 && draw < 10 && antkit::algorithms::version_number() >= 100;
  std::printf("consumer: grid %zu cells, draw %u, hash %s: %s\n", grid.size(), draw,
              antkit::kernel::hash_hex(hash.finish()).c_str(), ok ? "ok" : "FAILED");
  return ok ? 0 : 1;
}
