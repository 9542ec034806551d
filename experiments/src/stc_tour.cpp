#include <antkit/experiments/drawing.hpp>
#include <antkit/experiments/stc_tour.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/path_format.hpp>
#include <charconv>
#include <string_view>

namespace antkit::experiments {

namespace {

// An ostream through a large buffer; numbers written with to_chars.
class Out {
public:
  explicit Out(std::ostream& sink) : sink_(sink) { buf_.reserve(kBuffer + 64); }
  ~Out() { flush(); }
  Out(const Out&) = delete;
  Out& operator=(const Out&) = delete;
  Out& operator<<(std::string_view s) {
    buf_.append(s);
    if (buf_.size() >= kBuffer) flush();
    return *this;
  }
  Out& operator<<(std::int64_t v) {
    char digits[24];
    const auto end = std::to_chars(digits, digits + sizeof digits, v).ptr;
    return *this << std::string_view(digits, static_cast<std::size_t>(end - digits));
  }
  void flush() {
    sink_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
    buf_.clear();
  }

private:
  static constexpr std::size_t kBuffer = std::size_t{1} << 20;
  std::ostream& sink_;
  std::string buf_;
};

} // namespace

stc::RunResult write_stc_tour(const kernel::OccupancyGrid& map, kernel::Cell start,
                              stc::Variant variant, const stc::NoiseModel& noise,
                              const StcTourOutput& o) {
  stc::RunOptions run;
  run.noise = noise;
  run.record_path = o.keep_path;
  stc::path_format::TourWriter* path_file = nullptr;
  std::optional<Out> json;
  std::int64_t written = 0;
  const auto head = [&] {
    json.emplace(*o.json);
    *json << "{\n  \"variant\": \"" << stc::variant_name(variant)
          << "\",\n  \"width\": " << std::int64_t{map.width()}
          << ",\n  \"height\": " << std::int64_t{map.height()} << ",\n  \"start\": ["
          << std::int64_t{start.x} << ", " << std::int64_t{start.y} << "],\n  \"path\": [";
  };
  if (o.json || !o.path_file.empty())
    run.on_position = [&](stc::SubCell s) {
      if (o.json) {
        if (written == 0) head();
        *json << (written == 0       ? "\n    ["
                  : written % 8 == 0 ? ",\n    ["
                                     : ", [")
              << std::int64_t{s.x} << ", " << std::int64_t{s.y} << "]";
        ++written;
      }
      if (path_file) path_file->add(s);
    };
  stc::RunResult r;
  const auto tour = [&] {
    try {
      r = stc::run_stc(map, start, variant, run);
    } catch (const kernel::InputError& e) { // name the start as the caller does
      throw kernel::InputError(o.start_where, e.message());
    }
  };
  if (o.path_file.empty()) {
    tour();
  } else {
    io::write_file_atomic(o.path_file, [&](std::ostream& file) {
      stc::path_format::TourWriter writer(file, o.binary_path, map.width(), map.height(), start);
      path_file = &writer;
      tour();
      writer.finish();
      path_file = nullptr;
    });
  }
  if (o.json) {
    if (!json) head();
    *json << (written > 0 ? "\n  ],\n" : "],\n")
          << "  \"reachable_subcells\": " << r.reachable_subcells
          << ",\n  \"covered\": " << r.covered << ",\n  \"repeats\": " << r.repeats
          << ",\n  \"returned_to_start\": " << (r.returned_to_start ? "true" : "false")
          << ",\n  \"hash\": \"" << kernel::hash_hex(r.hash) << "\"";
    if (o.seed)
      *json << ",\n  \"noise_ppm\": " << std::int64_t{noise.ppm}
            << ",\n  \"seed\": " << static_cast<std::int64_t>(*o.seed);
    *json << "\n}\n";
    json->flush();
  }
  return r;
}

void save_stc_tour_figure(const kernel::OccupancyGrid& map, const stc::RunResult& r,
                          const std::string& map_name, const std::filesystem::path& svg,
                          const std::filesystem::path& png) {
  save_tour_figure(map, r.path, std::string(stc::variant_name(r.variant)) + " STC on " + map_name,
                   std::to_string(r.reachable_subcells) + " reachable sub-cells, " +
                       std::to_string(r.covered) + " covered, " + std::to_string(r.repeats) +
                       " repeats, back at the start cell: " + (r.returned_to_start ? "yes" : "no") +
                       ".",
                   svg, png);
}

} // namespace antkit::experiments
