#include <algorithm>
#include <antkit/experiments/buffon_figures.hpp>
#include <antkit/experiments/stc_tours.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/testing/stc_audit.hpp>
#include <antkit/uniform/scenario.hpp>
#include <sstream>

namespace antkit::experiments {

namespace {

constexpr std::int32_t kRandomSide = 64;
constexpr std::uint32_t kRandomDensityPpm = 100000; // 10 %

std::vector<std::filesystem::path> shared_maps(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  const auto movingai = dir / "movingai";
  if (dir.empty() || !std::filesystem::is_directory(movingai, ec)) return files;
  for (const auto& entry : std::filesystem::directory_iterator(movingai, ec))
    if (entry.path().extension() == ".map") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string random_name(int k) {
  return "random-64-64-10 #" + std::to_string(k);
}

std::string ppm_text(std::uint32_t ppm) {
  return number(static_cast<double>(ppm) / 1e6);
}

} // namespace

kernel::OccupancyGrid stc_experiment_map(const StcToursParams& params, const std::string& name) {
  for (const auto& file : shared_maps(params.maps_dir))
    if (file.filename().string() == name) return maps::load_map(file.string()).cells;
  for (int k = 0; k < params.random_maps; ++k)
    if (random_name(k) == name)
      return uniform::random_obstacles(kRandomSide, kRandomSide, kRandomDensityPpm, params.seed,
                                       static_cast<std::uint64_t>(k));
  throw kernel::InputError(name, "no such map in the STC experiment");
}

std::vector<StcNoisePoint> run_stc_noise(const kernel::OccupancyGrid& map, kernel::Cell start,
                                         const std::vector<std::string>& variants,
                                         const std::vector<std::uint32_t>& ppm, int trials,
                                         std::uint64_t seed, const algorithms::Runner& runner,
                                         std::int64_t* reachable, std::uint64_t* hash) {
  std::vector<stc::Variant> vs;
  for (const auto& name : variants) {
    const auto v = stc::parse_variant(name);
    if (!v || (*v != stc::Variant::Ant && *v != stc::Variant::AntEdge))
      throw kernel::InputError("variant", "marker noise applies to ant and ant-edge only");
    vs.push_back(*v);
  }
  // A bad start is refused here, on every rank, before any unit runs.
  stc::RunOptions quiet;
  quiet.record_path = false;
  const std::int64_t reach =
      stc::run_stc(map, start, vs.empty() ? stc::Variant::Ant : vs[0], quiet).reachable_subcells;
  const std::size_t levels = ppm.size(), n = static_cast<std::size_t>(std::max(0, trials));
  const auto units = algorithms::run_units(
      runner, "paper 002, marker noise", vs.size() * levels * n, [&](std::uint64_t u) {
        const stc::Variant v = vs[u / (levels * n)];
        stc::RunOptions run;
        run.noise = {ppm[(u / n) % levels], seed, static_cast<std::uint64_t>(u % n)};
        run.record_path = false;
        const auto r = stc::run_stc(map, start, v, run);
        algorithms::Payload p;
        p.put_i(r.covered);
        p.put_i(r.repeats);
        p.put(r.covered == r.reachable_subcells && r.returned_to_start ? 1 : 0);
        p.put_i(r.positions);
        p.put(r.hash);
        return p;
      });
  std::vector<StcNoisePoint> points;
  if (reachable) *reachable = reach;
  if (!runner.root()) return points;
  kernel::TraceHash digest;
  const double all = static_cast<double>(reach);
  for (std::size_t vi = 0; vi < vs.size(); ++vi)
    for (std::size_t level = 0; level < levels; ++level) {
      StcNoisePoint point;
      point.variant = std::string(stc::variant_name(vs[vi]));
      point.ppm = ppm[level];
      for (std::size_t t = 0; t < n; ++t) {
        algorithms::Payload p = units[(vi * levels + level) * n + t];
        point.coverage += static_cast<double>(p.get_i()) / all;
        point.repeats_per_subcell += static_cast<double>(p.get_i()) / all;
        point.complete += static_cast<double>(p.get());
        point.mean_positions += static_cast<double>(p.get_i());
        digest.add_u64(p.get());
      }
      const double d = static_cast<double>(n);
      point.coverage /= d;
      point.repeats_per_subcell /= d;
      point.complete /= d;
      point.mean_positions /= d;
      points.push_back(point);
    }
  if (hash) *hash = digest.finish();
  return points;
}

StcTours run_stc_tours(const StcToursParams& params, const algorithms::Runner& runner) {
  StcTours out;
  out.params = params;
  std::vector<kernel::OccupancyGrid> grids;
  for (const auto& file : shared_maps(params.maps_dir)) {
    grids.push_back(maps::load_map(file.string()).cells);
    out.maps.push_back(file.filename().string());
  }
  for (int k = 0; k < params.random_maps; ++k) {
    grids.push_back(uniform::random_obstacles(kRandomSide, kRandomSide, kRandomDensityPpm,
                                              params.seed, static_cast<std::uint64_t>(k)));
    out.maps.push_back(random_name(k));
  }
  const std::size_t variants = stc::kVariants.size();
  const auto tours = algorithms::run_units(
      runner, "paper 002, tours", grids.size() * variants, [&](std::uint64_t u) {
        const auto& map = grids[u / variants];
        const stc::Variant v = stc::kVariants[u % variants];
        algorithms::Payload p;
        const auto start = stc::default_start(map, v);
        if (!start) {
          p.put(0); // no place to start: an empty row
          return p;
        }
        const auto r = stc::run_stc(map, *start, v);
        const auto audit = testing::audit_stc_tour(map, *start, r.path,
                                                   stc::is_exact(v) ? testing::TourRule::ExactlyOnce
                                                                    : testing::TourRule::Coverage);
        p.put(1);
        p.put_i(r.reachable_subcells);
        p.put_i(r.positions);
        p.put_i(r.covered);
        p.put_i(r.repeats);
        p.put(r.returned_to_start ? 1 : 0);
        p.put(r.closed ? 1 : 0);
        p.put(audit.first.ok ? 1 : 0);
        p.put(r.hash);
        p.put_text(audit.first.ok ? "" : audit.first.describe());
        return p;
      });

  // The noise curve.
  std::size_t noise_index =
      grids.size() - static_cast<std::size_t>(std::max(0, params.random_maps));
  for (std::size_t i = 0; i < out.maps.size(); ++i)
    if (out.maps[i] == "den312d.map") noise_index = i;
  if (noise_index >= grids.size()) noise_index = 0;
  const bool have_noise_map = !grids.empty();
  const auto noise_start =
      have_noise_map ? stc::default_start(grids[noise_index], stc::Variant::Ant) : std::nullopt;
  std::uint64_t noise_hash = 0;
  if (noise_start)
    out.noise =
        run_stc_noise(grids[noise_index], *noise_start, {"ant", "ant-edge"}, params.noise_ppm,
                      params.noise_trials, params.seed, runner, &out.noise_reachable, &noise_hash);
  if (!runner.root()) return out;

  kernel::TraceHash digest;
  for (std::size_t u = 0; u < tours.size(); ++u) {
    algorithms::Payload p = tours[u];
    StcTourRow row;
    row.map = out.maps[u / variants];
    row.variant = std::string(stc::variant_name(stc::kVariants[u % variants]));
    if (p.get() == 1) {
      row.reachable = p.get_i();
      row.positions = p.get_i();
      row.covered = p.get_i();
      row.repeats = p.get_i();
      row.returned_to_start = p.get() != 0;
      row.closed = p.get() != 0;
      row.audit_ok = p.get() != 0;
      row.hash = p.get();
      row.audit = p.get_text();
      digest.add_u64(row.hash);
    } else {
      row.audit = "no free place to start";
    }
    out.tours.push_back(std::move(row));
  }
  if (noise_start) {
    out.noise_map = out.maps[noise_index];
    digest.add_u64(noise_hash);
  }
  out.hash = digest.finish();
  return out;
}

std::string stc_tours_csv(const StcTours& t) {
  std::ostringstream s;
  s << "map,variant,reachable_subcells,positions,covered,repeats,returned_to_start,closed,"
       "audit_ok,audit,hash\n";
  for (const auto& r : t.tours)
    s << '"' << r.map << "\"," << r.variant << ',' << r.reachable << ',' << r.positions << ','
      << r.covered << ',' << r.repeats << ',' << (r.returned_to_start ? "yes" : "no") << ','
      << (r.closed ? "yes" : "no") << ',' << (r.audit_ok ? "yes" : "no") << ",\"" << r.audit
      << "\"," << kernel::hash_hex(r.hash) << '\n';
  return s.str();
}

std::string stc_noise_csv(const StcTours& t) {
  std::ostringstream s;
  s << "map,variant,misread_probability,trials,coverage,repeats_per_subcell,complete_tours\n";
  for (const auto& p : t.noise)
    s << '"' << t.noise_map << "\"," << p.variant << ',' << ppm_text(p.ppm) << ','
      << t.params.noise_trials << ',' << number(p.coverage) << ',' << number(p.repeats_per_subcell)
      << ',' << number(p.complete) << '\n';
  return s.str();
}

Figure stc_noise_plot(const StcTours& t) {
  Figure fig;
  fig.title = "Paper 002: ant-like STC against marker noise";
  fig.x_label = "probability that one mark reading is wrong";
  fig.y_label = "mean over the trials";
  fig.x_axis = Axis::Log;
  fig.y_from_zero = true;
  fig.caption = "Map " + t.noise_map + " (" + std::to_string(t.noise_reachable) +
                " reachable sub-cells), " + std::to_string(t.params.noise_trials) +
                " keyed trials per level, seed " + std::to_string(t.params.seed) +
                "; the noise-free level (0) is not on the log axis: every tour there is exact.";
  const char* colours[] = {"#1e5bd8", "#d81e1e"};
  for (const int which : {0, 1, 2}) {
    PlotPanel panel;
    panel.title = which == 0   ? "coverage (fraction of reachable sub-cells)"
                  : which == 1 ? "repeats per reachable sub-cell"
                               : "complete tours (fraction)";
    for (std::size_t v = 0; v < 2; ++v) {
      PlotSeries s{v == 0 ? "ant" : "ant-edge", colours[v], false, false, {}};
      for (const auto& p : t.noise)
        if (p.variant == s.name && p.ppm > 0)
          s.points.push_back({static_cast<double>(p.ppm) / 1e6,
                              which == 0   ? p.coverage
                              : which == 1 ? p.repeats_per_subcell
                                           : p.complete,
                              std::nullopt, std::nullopt});
      panel.series.push_back(std::move(s));
    }
    fig.panels.push_back(std::move(panel));
  }
  fig.legend = fig.panels.front().series; // the same two variants in every panel: one legend
  return fig;
}

} // namespace antkit::experiments
