#pragma once
// One STC tour written as it is made (`antkit stc`, issue 15): the path streamed into a JSON
// document and into a path file (CSV "x,y" lines, or the two-bits-per-move binary of
// stc/path_format.hpp), never held unless asked for (a picture), so that a tour of a map of
// millions of sub-cells costs the map and a bit per sub-cell.
//
// The JSON document's keys, in order: variant, width, height, start, path (eight positions to a
// line), reachable_subcells, covered, repeats, returned_to_start, hash, and with marker noise
// noise_ppm and seed. Its first byte is written after run_stc has accepted the start, so a bad
// start leaves no output; the path file goes through io::write_file_atomic (whole or not at
// all).
#include <antkit/kernel/grid.hpp>
#include <antkit/stc/world.hpp>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>

namespace antkit::experiments {

struct StcTourOutput {
  std::ostream* json = nullptr;        // the JSON document, streamed; null: none
  std::filesystem::path path_file;     // empty: none
  bool binary_path = false;            // path_file in the binary form (else CSV)
  bool keep_path = false;              // RunResult::path kept (a picture)
  std::optional<std::uint64_t> seed{}; // the noise's seed, when noise was asked for (the JSON's
                                       // noise_ppm and seed keys)
  std::string start_where = "start";   // names the start in an InputError for a bad start
};

// Runs `variant` from `start` on `map` with `noise` (run_stc) and writes what `out` asks for.
// Throws kernel::InputError(out.start_where, ...) for a start run_stc refuses, and
// InputError(path_file, ...) for a path file that cannot be written.
[[nodiscard]] stc::RunResult write_stc_tour(const kernel::OccupancyGrid& map, kernel::Cell start,
                                            stc::Variant variant, const stc::NoiseModel& noise,
                                            const StcTourOutput& out);

// The picture of a tour run with keep_path (save_tour_figure): titled with its variant and
// `map_name`, with a caption of its counts. Throws kernel::InputError for a file that cannot be
// written.
void save_stc_tour_figure(const kernel::OccupancyGrid& map, const stc::RunResult& result,
                          const std::string& map_name, const std::filesystem::path& svg,
                          const std::filesystem::path& png);

} // namespace antkit::experiments
