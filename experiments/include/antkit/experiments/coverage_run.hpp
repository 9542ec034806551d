#pragma once
// One coverage run of paper 004 as `antkit cover` makes it, with what it writes: the trace that
// `antkit check cover` reads (testing/run_audit.hpp, read_cover_trace) and the picture of the
// final state.
#include <antkit/uniform/coverage.hpp>
#include <antkit/uniform/world.hpp>
#include <cstdint>
#include <filesystem>
#include <string>

namespace antkit::experiments {

// run_coverage, with the poses after every tick (tick 0: the start) streamed into `trace` as the
// trace format: two comment lines (what it is, "# sensor: R"), the header
// "tick,robot,x,y,bearing", a line per robot per tick, then the run's claims "# claim viewed: V"
// and "# claim viewable: W". The file is written whole or not at all (write_file_atomic; an
// InputError names it when it cannot be written). `sensor` is the world's sensor distance.
uniform::CoverageResult run_coverage_traced(uniform::CoverageWorld& world,
                                            uniform::Algorithm algorithm, std::uint64_t seed,
                                            std::uint64_t trial, std::uint64_t limit,
                                            std::int64_t sensor,
                                            const std::filesystem::path& trace);

// The final state of `world` after `result`: viewed and unviewed free cells, obstacles, unknown
// cells, the robots; legend, and a caption with the coverage (2 decimals), the movements and why
// the run stopped. `algorithm` titles it as the caller names it; `sensor` is the sensor distance.
void save_coverage_figure(const std::string& algorithm, const uniform::CoverageWorld& world,
                          const uniform::CoverageResult& result, std::int64_t sensor,
                          const std::filesystem::path& svg, const std::filesystem::path& png);

} // namespace antkit::experiments
