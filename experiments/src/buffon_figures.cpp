#include <algorithm>
#include <antkit/buffon/checkpoints.hpp>
#include <antkit/buffon/estimate.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/experiments/buffon_figures.hpp>
#include <antkit/experiments/calibration.hpp>
#include <antkit/experiments/drawing.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/geometry/fixed_convert.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace antkit::experiments {

namespace buffon = antkit::buffon;
namespace geometry = antkit::geometry;
using kernel::InputError;

namespace {

void check(const BuffonFigureParams& p) {
  if (p.trials < 1 || p.trials > 100000)
    throw InputError("trials", "the number of trials must be in [1, 100000]");
  if (p.steps < 1 || p.steps > 100000000)
    throw InputError("steps per visit", "the number of steps must be in [1, 10^8]");
}

const char* const kColours[] = {"#1e5bd8", "#d81e1e", "#1b9e3a", "#e08a00",
                                "#7b3fb5", "#00a0a0", "#a0a000", "#606060"};

} // namespace

std::vector<BuffonArena> buffon_figure_arenas(int figure) {
  std::vector<BuffonArena> pts;
  const double diameters[] = {10, 20, 30, 40, 50, 60, 70, 80, 90, 100};
  switch (figure) {
  case 5:
    for (double d : diameters) pts.push_back({"circle", d, "circle:d=" + number(d), 0.1});
    for (double d : diameters) pts.push_back({"square", d, "square:d=" + number(d), 0.1});
    break;
  case 6:
    pts.push_back({"standard", 1, "standard", 0.1});
    for (double e : {0.968, 0.994, 0.998})
      pts.push_back({"ellipse", 1 / std::sqrt(1 - e * e), "ellipse:area=7854,e=" + number(e), 0.1});
    break;
  case 7:
    pts.push_back({"none", 0, "standard", 0.1});
    for (int k = 1; k <= 8; ++k) {
      pts.push_back({"barrier-i", 10.0 * k, "barrier-i:len=" + number(0.1 * k), 0.1});
      pts.push_back({"barrier-plus", 10.0 * k, "barrier-plus:len=" + number(0.1 * k), 0.1});
    }
    break;
  case 8: {
    double x = 0;
    for (const char* s : {"standard", "ring", "plus", "obstacles"}) pts.push_back({s, x++, s, 0.1});
    break;
  }
  case 9:
    for (double w : {0.05, 0.1, 0.2, 0.4})
      for (double d : diameters) pts.push_back({"w=" + number(w), d, "circle:d=" + number(d), w});
    break;
  default:
    break;
  }
  return pts;
}

BuffonFigureTrials::BuffonFigureTrials(const BuffonFigureParams& params) : params_(params) {
  arenas_ = buffon_figure_arenas(params.figure);
  if (arenas_.empty()) throw InputError("figure", "the figure must be 5, 6, 7, 8 or 9 (or 14)");
  check(params);
  for (std::size_t k = 0; k < arenas_.size(); ++k)
    areas_.push_back(geometry::build_arena_spec(arenas_[k].spec, "figure").arena.area());
  payloads_.resize(arenas_.size());
  have_.assign(arenas_.size(), 0);
}

void BuffonFigureTrials::extend(std::int64_t trials, const algorithms::Runner& runner) {
  extend(trials, std::vector<bool>(arenas_.size(), true), runner);
}

void BuffonFigureTrials::extend(std::int64_t trials, const std::vector<bool>& arenas,
                                const algorithms::Runner& runner) {
  BuffonFigureParams wanted = params_;
  wanted.trials = trials;
  check(wanted);
  if (arenas.size() != arenas_.size())
    throw std::invalid_argument("BuffonFigureTrials::extend: one flag per arena");
  // The trials to run, arena by arena in row order: [have_[k], trials) of each arena asked for.
  // With every arena at one count this is the one run's unit order (arena, then trial), so the
  // payloads, and the figure, are the same whatever the batches.
  struct Range {
    std::size_t arena;
    std::uint64_t first, count, offset;
  };
  std::vector<Range> ranges;
  std::uint64_t units = 0;
  for (std::size_t k = 0; k < arenas_.size(); ++k)
    if (arenas[k] && trials > have_[k]) {
      const auto first = static_cast<std::uint64_t>(have_[k]);
      ranges.push_back({k, first, static_cast<std::uint64_t>(trials) - first, units});
      units += ranges.back().count;
    }
  if (ranges.empty()) return;
  std::vector<buffon::World> worlds;
  std::vector<buffon::TrialParams> trial_params;
  for (const auto& r : ranges) {
    const std::size_t k = r.arena;
    worlds.emplace_back(geometry::build_arena_spec(arenas_[k].spec, "figure").arena.walls_fx());
    buffon::TrialParams tp;
    tp.seed = params_.seed;
    tp.experiment = 4000 + 100 * static_cast<std::uint64_t>(params_.figure) + k;
    tp.steps = params_.steps;
    tp.width = geometry::fixed_from_double<kernel::Fx>(arenas_[k].width, "trail width");
    trial_params.push_back(tp);
  }
  const auto payloads = algorithms::run_units(
      runner, "paper 000, figure " + std::to_string(params_.figure), units, [&](std::uint64_t u) {
        std::size_t i = 0;
        while (u >= ranges[i].offset + ranges[i].count) ++i;
        const auto r =
            buffon::run_trial(worlds[i], trial_params[i], ranges[i].first + (u - ranges[i].offset));
        algorithms::Payload p;
        p.put(r.bc);
        p.put_i(r.length1_raw);
        p.put_i(r.length2_raw);
        p.put(r.crossings_exact);
        p.put(r.blocked);
        p.put(r.hash);
        return p;
      });
  for (const auto& r : ranges) {
    if (runner.root())
      for (std::uint64_t t = 0; t < r.count; ++t)
        payloads_[r.arena].push_back(payloads[r.offset + t]);
    have_[r.arena] = trials;
  }
}

std::int64_t BuffonFigureTrials::trials() const noexcept {
  std::int64_t most = 0;
  for (const auto n : have_) most = std::max(most, n);
  return most;
}

BuffonFigure BuffonFigureTrials::finish() const {
  BuffonFigure out{params_, {}, 0};
  out.params.trials = trials();
  kernel::TraceHash digest;
  for (std::size_t k = 0; k < arenas_.size() && !payloads_[k].empty(); ++k) {
    std::vector<double> nbc, cf, blocked, length1, bc_values;
    for (algorithms::Payload p : payloads_[k]) {
      const auto bc = p.get();
      const double l1 = static_cast<double>(p.get_i()) / 65536.0;
      const double l2 = static_cast<double>(p.get_i()) / 65536.0;
      const auto crossings = p.get();
      blocked.push_back(static_cast<double>(p.get()));
      digest.add_u64(p.get());
      nbc.push_back(l2 > 0 ? static_cast<double>(bc) / l2 : 0.0);
      length1.push_back(l1);
      bc_values.push_back(static_cast<double>(bc));
      if (auto a = buffon::closed_form_area(l1, l2, crossings).area) cf.push_back(*a);
    }
    out.rows.push_back({arenas_[k], areas_[k], buffon::quantile(nbc, 0.5),
                        buffon::quantile(nbc, 0.25), buffon::quantile(nbc, 0.75),
                        buffon::quantile(cf, 0.5), buffon::quantile(blocked, 0.5)});
    auto& row = out.rows.back();
    row.trials = static_cast<std::int64_t>(payloads_[k].size());
    row.length1_median = buffon::quantile(length1, 0.5);
    row.efficiency =
        row.length1_median > 0 ? row.nbc_median * M_PI * row.area / (2 * row.length1_median) : 0.0;
    row.nbc_trials = std::move(nbc);
    row.length1_trials = std::move(length1);
    row.bc_trials = std::move(bc_values);
  }
  out.hash = digest.finish();
  return out;
}

BuffonFigure run_buffon_figure(const BuffonFigureParams& params, const algorithms::Runner& runner) {
  BuffonFigureTrials trials(params);
  trials.extend(params.trials, runner);
  if (!runner.root()) return BuffonFigure{params, {}, 0};
  return trials.finish();
}

std::string buffon_figure_csv(const BuffonFigure& f) {
  std::ostringstream csv;
  csv << "series,x,arena,width,area,trials,nbc_median,nbc_q1,nbc_q3,area_closed_form_median,"
         "blocked_median\n";
  for (const auto& r : f.rows)
    csv << r.arena.series << ',' << number(r.arena.x) << ",\"" << r.arena.spec << "\","
        << number(r.arena.width) << ',' << number(r.area) << ',' << r.trials << ','
        << number(r.nbc_median) << ',' << number(r.nbc_q1) << ',' << number(r.nbc_q3) << ','
        << number(r.closed_form_median) << ',' << number(r.blocked_median) << '\n';
  return csv.str();
}

namespace {

// "100 trials per arena", or, for a figure whose arenas `reproduce --decide` ran to different
// counts, the range ("200 to 12800 trials per arena (the CSV's trials column)").
std::string trials_per_arena(const BuffonFigure& f) {
  std::int64_t lo = f.params.trials, hi = 0;
  for (const auto& r : f.rows) lo = std::min(lo, r.trials), hi = std::max(hi, r.trials);
  if (f.rows.empty() || lo == hi) return std::to_string(f.params.trials) + " trials per arena";
  return std::to_string(lo) + " to " + std::to_string(hi) +
         " trials per arena (the CSV's trials column)";
}

// Buffon's efficiency of each trial, nBC pi A / (2 L1): 1 for an ideal needle count, below where
// the trails blend; the figure's point is the efficiency at the medians (as claims 000-4 and 000-10
// read it), its bar the interquartile range of the trials'.
PlotPoint efficiency_point(const BuffonFigureRow& r) {
  std::vector<double> e;
  for (std::size_t t = 0; t < r.nbc_trials.size() && t < r.length1_trials.size(); ++t)
    if (r.length1_trials[t] > 0)
      e.push_back(r.nbc_trials[t] * M_PI * r.area / (2 * r.length1_trials[t]));
  PlotPoint p{r.arena.x, r.efficiency, std::nullopt, std::nullopt};
  if (!e.empty()) p.lo = buffon::quantile(e, 0.25), p.hi = buffon::quantile(e, 0.75);
  return p;
}

// Figures 5 and 9: sizes that span a decade, so nBC (which falls as 1 / area) on log axes, and
// beside it the efficiency, linear, with the 0.9 threshold at which claims 000-4 and 000-10 call a
// circle blended.
// with_ideal: also draw Buffon's ideal count for the first series (one line per series would crowd
// a figure of several widths).
void nbc_and_efficiency(Figure& fig, PlotPanel& nbc, const BuffonFigure& f, bool with_ideal) {
  fig.x_axis = Axis::Log;
  fig.y_axis = Axis::Log;
  nbc.title = "nBC (log axes)";
  PlotPanel eff;
  eff.title = "Buffon efficiency nBC π A / (2 L1)";
  eff.y_axis = Axis::Linear;
  eff.y_label = "efficiency (1: no blending)";
  eff.y_from_zero = true;
  eff.marks.push_back({0.9, "0.9 (000-4, 000-10)", "#b00000", true});
  for (const auto& s : nbc.series) {
    PlotSeries e = s;
    e.points.clear();
    for (const auto& r : f.rows)
      if (r.arena.series == s.name) e.points.push_back(efficiency_point(r));
    eff.series.push_back(std::move(e));
  }
  // Buffon's ideal count for the first series (the circles), 2 L1 / (pi A) at the median L1: where
  // nBC falls below it the trails blend.
  if (with_ideal) {
    PlotSeries ideal{"no blending: 2 L1 / (π A)", "#606060", true, false, {}};
    for (const auto& r : f.rows)
      if (r.arena.series == nbc.series.front().name && r.area > 0)
        ideal.points.push_back(
            {r.arena.x, 2 * r.length1_median / (M_PI * r.area), std::nullopt, std::nullopt});
    nbc.series.push_back(std::move(ideal));
  }
  fig.legend = nbc.series; // one legend for both panels
  fig.panels = {nbc, std::move(eff)};
}

} // namespace

Figure buffon_figure_plot(const BuffonFigure& f) {
  Figure fig;
  PlotPanel panel;
  std::vector<std::string> names;
  for (const auto& r : f.rows)
    if (std::find(names.begin(), names.end(), r.arena.series) == names.end())
      names.push_back(r.arena.series);
  for (std::size_t s = 0; s < names.size(); ++s) {
    PlotSeries series;
    series.name = names[s];
    series.colour = kColours[s % 8];
    for (const auto& r : f.rows)
      if (r.arena.series == names[s])
        series.points.push_back({r.arena.x, r.nbc_median, r.nbc_q1, r.nbc_q3});
    panel.series.push_back(std::move(series));
  }
  const std::string trials =
      trials_per_arena(f) + ", " + std::to_string(f.params.steps) + " steps per visit";
  fig.y_label = "nBC (Buffon crossings per unit of visit 2)";
  fig.caption = "Median nBC with interquartile bars; " + trials + ", seed " +
                std::to_string(f.params.seed) + ".";
  // The standard circle's median nBC, the paper's baseline in Figures 6, 7 and 8.
  std::optional<double> baseline;
  for (const auto& r : f.rows)
    if (r.arena.spec == "standard") baseline = r.nbc_median;
  const auto baseline_mark = [&](const std::string& label) {
    return PlotMark{*baseline, label, "#404040", false, true};
  };
  switch (f.params.figure) {
  case 5:
    fig.title = "Paper 000, Figure 5: nBC of circles and squares";
    fig.x_label = "diameter d, robot diameters (squares: same area)";
    nbc_and_efficiency(fig, panel, f, true);
    fig.caption = "Medians with interquartile bars; " + trials + ", seed " +
                  std::to_string(f.params.seed) +
                  ".\nLeft: nBC falls as 1 / area, so log axes keep every size apart; the dashed "
                  "line is the count without blending.\nRight: nBC over that count; below 0.9 (red "
                  "line) the trails blend. The paper gives Figure 5 as a plot, no numbers.";
    return fig;
  case 9:
    fig.title = "Paper 000, Figure 9: trail width";
    fig.x_label = "diameter of the circle, robot diameters";
    nbc_and_efficiency(fig, panel, f, false);
    fig.caption = "Medians with interquartile bars; " + trials + ", seed " +
                  std::to_string(f.params.seed) +
                  ".\nLeft: nBC on log axes. Right: efficiency; below 0.9 (red line) the trails "
                  "blend,\nup to a larger circle for a wider trail (claim 000-10). The paper gives "
                  "Figure 9 as a plot, no numbers.";
    return fig;
  case 6:
    fig.title = "Paper 000, Figure 6: nBC against compactness";
    fig.x_label = "compactness r1 / r2 (1: the standard circle; ellipses of the same area)";
    for (auto& series : panel.series)
      if (series.name == "ellipse")
        for (std::size_t i = 0; i < series.points.size(); ++i) {
          // The eccentricity back from the compactness: e = sqrt(1 - (r2 / r1)^2).
          const double c = series.points[i].x;
          char label[32];
          std::snprintf(label, sizeof label, "e = %.3f", std::sqrt(1 - 1 / (c * c)));
          series.points[i].label = label;
        }
    if (baseline) panel.marks.push_back(baseline_mark("baseline: standard circle"));
    fig.caption += "\nThe dashed line is the paper's baseline, the standard circle's median nBC.";
    break;
  case 7: {
    fig.title = "Paper 000, Figure 7: barriers in the standard arena";
    fig.x_label = "barrier length, % of the diameter";
    // Figures 7a and 7b: one panel per barrier shape, the arena without a barrier as the dashed
    // baseline in both.
    PlotPanel i_panel{"Figure 7a: I-shaped barrier", "", {}, {}};
    PlotPanel plus_panel{"Figure 7b: plus-shaped barrier", "", {}, {}};
    for (auto& series : panel.series) {
      if (series.name == "barrier-i") i_panel.series.push_back(series);
      if (series.name == "barrier-plus") plus_panel.series.push_back(series);
    }
    if (baseline) fig.marks.push_back(baseline_mark("baseline: no barrier"));
    fig.caption += "\nThe dashed line is the paper's baseline, the standard circle's median nBC.";
    fig.panels = {std::move(i_panel), std::move(plus_panel)};
    return fig;
  }
  case 8: {
    fig.title = "Paper 000, Figure 8: holes and obstacles";
    fig.x_label = "arena";
    for (const auto& r : f.rows) fig.x_categories.push_back(r.arena.series);
    // Categories share one series so that each arena is one point.
    PlotSeries one;
    one.name = "median nBC";
    one.colour = kColours[0];
    for (std::size_t i = 0; i < f.rows.size(); ++i)
      one.points.push_back(
          {static_cast<double>(i), f.rows[i].nbc_median, f.rows[i].nbc_q1, f.rows[i].nbc_q3});
    one.hollow = true;
    panel.series.assign(1, std::move(one));
    if (baseline) panel.marks.push_back(baseline_mark("baseline: standard circle"));
    fig.caption += "\nThe dashed line is the standard circle's median nBC, as in Figures 6 and 7.";
    break;
  }
  default:
    break;
  }
  fig.panels.push_back(std::move(panel));
  return fig;
}

Figure buffon_figure5b_plot(const BuffonFigure& f) {
  Figure fig;
  fig.title = "Paper 000, Figure 5b: squares against circles of the same area";
  fig.x_label = "median nBC of the circle";
  fig.y_label = "median nBC of the square";
  fig.x_axis = Axis::Log;
  fig.y_axis = Axis::Log;
  fig.caption = "One point per diameter d, interquartile bars of the square; the dashed line is "
                "y = x (equal nBC).\nLog axes: nBC falls as 1 / area, so the larger arenas are "
                "spread out instead of crowding one corner.\n" +
                trials_per_arena(f) + ", seed " + std::to_string(f.params.seed) + ".";
  PlotPanel panel;
  PlotSeries points{"one diameter, d = 10 to 100", kColours[0], false, true, {}};
  double lo = 1e300, hi = 0;
  for (const auto& circle : f.rows) {
    if (circle.arena.series != "circle") continue;
    for (const auto& square : f.rows)
      if (square.arena.series == "square" && square.arena.x == circle.arena.x) {
        points.points.push_back({circle.nbc_median, square.nbc_median, square.nbc_q1, square.nbc_q3,
                                 "d=" + number(circle.arena.x)});
        lo = std::min({lo, circle.nbc_median, square.nbc_median});
        hi = std::max({hi, circle.nbc_median, square.nbc_median});
      }
  }
  PlotSeries diagonal{"y = x",
                      "#606060",
                      true,
                      false,
                      {{lo, lo, std::nullopt, std::nullopt}, {hi, hi, std::nullopt, std::nullopt}}};
  panel.series = {std::move(diagonal), std::move(points)};
  fig.panels.push_back(std::move(panel));
  return fig;
}

namespace {
constexpr int kFigure14Checkpoints = 10;
} // namespace

Figure14Trials::Figure14Trials(const BuffonFigureParams& params) : params_(params) {
  check(params);
  for (int d = 30; d <= 100; d += 10) {
    diameters_.push_back(d);
    areas_.push_back(
        geometry::build_arena_spec("circle:d=" + std::to_string(d), "figure").arena.area());
  }
  payloads_.resize(diameters_.size());
}

void Figure14Trials::extend(std::int64_t trials, const algorithms::Runner& runner) {
  BuffonFigureParams wanted = params_;
  wanted.trials = trials;
  check(wanted);
  if (trials <= have_) return;
  const std::int64_t step_raw = std::int64_t{168} * 65536;
  std::vector<buffon::World> worlds;
  std::vector<buffon::TrialParams> trial_params;
  for (const int d : diameters_) {
    worlds.emplace_back(
        geometry::build_arena_spec("circle:d=" + std::to_string(d), "figure").arena.walls_fx());
    buffon::TrialParams tp;
    tp.seed = params_.seed;
    tp.experiment = 4000 + 100 * 14 + static_cast<std::uint64_t>(d);
    tp.steps = params_.steps;
    trial_params.push_back(tp);
  }
  const auto first = static_cast<std::uint64_t>(have_);
  const auto batch = static_cast<std::uint64_t>(trials - have_);
  const auto payloads = algorithms::run_units(
      runner, "paper 000, figure 14", diameters_.size() * batch, [&](std::uint64_t u) {
        const std::size_t k = u / batch;
        const auto r = buffon::run_checkpoints(worlds[k], trial_params[k], first + u % batch,
                                               step_raw, kFigure14Checkpoints);
        algorithms::Payload p;
        p.put(r.bc.size());
        for (std::size_t i = 0; i < r.bc.size(); ++i) {
          p.put(r.bc[i]);
          p.put_i(r.length2_raw[i]);
          p.put(r.rs_cells[i]);
        }
        p.put_i(r.rs_cell_raw);
        return p;
      });
  if (runner.root())
    for (std::size_t k = 0; k < diameters_.size(); ++k)
      for (std::uint64_t t = 0; t < batch; ++t) payloads_[k].push_back(payloads[k * batch + t]);
  have_ = trials;
}

Figure14 Figure14Trials::finish() const {
  Figure14 out{params_, {}, 0};
  out.params.trials = have_;
  kernel::TraceHash digest;
  std::vector<Figure14Arena> arenas;
  for (std::size_t k = 0; k < diameters_.size(); ++k) {
    Figure14Arena a{static_cast<double>(diameters_[k]), areas_[k], {}, {}};
    for (algorithms::Payload p : payloads_[k]) {
      for (const std::uint64_t w : p.words()) digest.add_u64(w);
      buffon::CheckpointResult r;
      const auto n = p.get();
      for (std::uint64_t i = 0; i < n; ++i) {
        r.bc.push_back(p.get());
        r.length2_raw.push_back(p.get_i());
        r.rs_cells.push_back(p.get());
      }
      r.rs_cell_raw = p.get_i();
      add_checkpoints(a, r);
    }
    arenas.push_back(std::move(a));
  }
  if (have_ > 0)
    for (std::size_t k = 0; k < kFigure14Checkpoints; ++k) {
      const auto fit = calibrate_at(arenas, k);
      const double total = 2.0 * 168.0 * static_cast<double>(k + 1);
      for (const auto& a : arenas) {
        if (is_calibration_diameter(a.diameter)) continue;
        const std::vector<double> est = estimates_at(a, k, fit);
        out.rows.push_back({a.diameter, total, a.area, buffon::quantile(est, 0.5),
                            buffon::quantile(est, 0.25), buffon::quantile(est, 0.75),
                            buffon::quantile(a.rs[k], 0.5), buffon::quantile(a.rs[k], 0.25),
                            buffon::quantile(a.rs[k], 0.75), fit.a, fit.b, fit.c});
      }
    }
  out.hash = digest.finish();
  out.arenas = std::move(arenas);
  return out;
}

Figure14 run_figure14(const BuffonFigureParams& params, const algorithms::Runner& runner) {
  Figure14Trials trials(params);
  trials.extend(params.trials, runner);
  if (!runner.root()) return Figure14{params, {}, 0};
  return trials.finish();
}

std::string figure14_csv(const Figure14& f) {
  std::ostringstream csv;
  csv << "diameter,total_length,area,buffon_median,buffon_q1,buffon_q3,rs_median,rs_q1,rs_q3,"
         "fit_a,fit_b,fit_c\n";
  for (const auto& r : f.rows)
    csv << number(r.diameter) << ',' << number(r.total_length) << ',' << number(r.area) << ','
        << number(r.buffon_median) << ',' << number(r.buffon_q1) << ',' << number(r.buffon_q3)
        << ',' << number(r.rs_median) << ',' << number(r.rs_q1) << ',' << number(r.rs_q3) << ','
        << number(r.fit_a) << ',' << number(r.fit_b) << ',' << number(r.fit_c) << '\n';
  return csv.str();
}

Figure figure14_plot(const Figure14& f) {
  Figure fig;
  fig.title = "Paper 000, Figure 14: calibrated Buffon and RS estimates";
  fig.x_label = "total trail length (both visits), robot diameters";
  fig.y_label = "estimate / true area";
  fig.y_marks = {1.0};
  fig.caption = "Medians with interquartile bars over " + std::to_string(f.params.trials) +
                " trials; Buffon calibrated on circles d = 30, 50, 70, 90 (dashed line: exact).";
  std::vector<double> diameters;
  for (const auto& r : f.rows)
    if (std::find(diameters.begin(), diameters.end(), r.diameter) == diameters.end())
      diameters.push_back(r.diameter);
  PlotPanel buffon_panel{"calibrated Buffon", "", {}, {}},
      rs_panel{"Random Search (RS)", "", {}, {}};
  for (std::size_t i = 0; i < diameters.size(); ++i) {
    PlotSeries b{"circle d=" + number(diameters[i]), kColours[i % 8], false, false, {}};
    PlotSeries r = b;
    for (const auto& row : f.rows) {
      if (row.diameter != diameters[i]) continue;
      b.points.push_back({row.total_length, row.buffon_median / row.area, row.buffon_q1 / row.area,
                          row.buffon_q3 / row.area});
      r.points.push_back(
          {row.total_length, row.rs_median / row.area, row.rs_q1 / row.area, row.rs_q3 / row.area});
    }
    buffon_panel.series.push_back(std::move(b));
    rs_panel.series.push_back(std::move(r));
  }
  fig.legend = buffon_panel.series; // the same circles in both panels: one legend
  fig.panels = {std::move(buffon_panel), std::move(rs_panel)};
  return fig;
}

void save_trial_trails_figure(const std::string& name, const geometry::Arena& arena,
                              const buffon::TrialResult& t, std::int64_t steps,
                              const std::filesystem::path& svg, const std::filesystem::path& png) {
  TrailPanel panel;
  panel.title = name + " (area " + number(arena.area()) + ")";
  for (const auto& ring : arena.rings()) {
    std::vector<XY> pts;
    for (const auto& p : ring) pts.emplace_back(p[0], p[1]);
    panel.rings.push_back(std::move(pts));
  }
  // Every 4th point (steps are 0.04 units), and both ends of every jump longer than a step (the
  // pieces of a marker's trail under --rule markers), so that no chord is drawn across the arena.
  const auto thin = [](const std::vector<kernel::FxPoint>& pts) {
    std::vector<XY> out;
    const auto at = [&](std::size_t i) {
      return XY{geometry::to_double(pts[i].x), geometry::to_double(pts[i].y)};
    };
    const auto jump = [&](std::size_t i) { // between i and i + 1
      const auto [ax, ay] = at(i);
      const auto [bx, by] = at(i + 1);
      return std::hypot(bx - ax, by - ay) > 1.0;
    };
    for (std::size_t i = 0; i < pts.size(); ++i)
      if (i % 4 == 0 || i + 1 == pts.size() || jump(i) || (i > 0 && jump(i - 1)))
        out.push_back(at(i));
    return out;
  };
  panel.trail1 = thin(t.trail1);
  panel.trail2 = thin(t.trail2);
  save_trails_figure(
      "Buffon's needle, trial 0 (paper 000)",
      std::to_string(t.steps1 > 0 ? t.steps1 : steps) + " and " +
          std::to_string(t.steps2 > 0 ? t.steps2 : steps) + " steps; " +
          (t.bc > 0 ? std::to_string(t.bc) + " crossings counted (BC), " : std::string()) +
          std::to_string(t.crossings_exact) + " exact crossings of the two trails.",
      {panel}, svg, png);
}

} // namespace antkit::experiments
