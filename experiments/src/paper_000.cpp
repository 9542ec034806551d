// Paper 000 in a reproduction (papers.hpp): Figures 5-9 and 14, each figure a unit that --decide
// extends trial by trial (BuffonFigureTrials: trial t keyed by t alone), and Figure 4's trails.
#include <algorithm>
#include <antkit/buffon/measurement.hpp>
#include <antkit/experiments/buffon_figures.hpp>
#include <antkit/experiments/drawing.hpp>
#include <antkit/experiments/format.hpp>
#include <antkit/experiments/papers.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/geometry/fixed_convert.hpp>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace antkit::experiments {

namespace {

std::string buffon_rows_table(const BuffonFigure& f) {
  std::ostringstream s;
  s << "| series | x | arena | median nBC | IQR | efficiency |\n|---|---|---|---|---|---|\n";
  for (const auto& r : f.rows)
    s << "| " << r.arena.series << " | " << number(r.arena.x) << " | `" << r.arena.spec << "` | "
      << fixed(r.nbc_median, 4) << " | " << fixed(r.nbc_q1, 4) << " - " << fixed(r.nbc_q3, 4)
      << " | " << fixed(r.efficiency, 3) << " |\n";
  return s.str();
}

// Figure 4: the trails of trial 0 in three circles (experiment 4400 + k).
void buffon_figure4(ReportFiles& w, std::uint64_t seed) {
  std::vector<TrailPanel> panels;
  const double diameters[] = {20, 50, 100};
  for (std::size_t k = 0; k < 3; ++k) {
    const auto arena =
        geometry::build_arena_spec("circle:d=" + number(diameters[k]), "figure").arena;
    buffon::TrialParams params;
    params.seed = seed;
    params.experiment = 4400 + k;
    params.keep_trails = true;
    const auto r = buffon::run_trial(buffon::World(arena.walls_fx()), params, 0);
    TrailPanel p;
    p.title = "circle, d = " + number(diameters[k]) + " (area " + fixed(arena.area(), 0) + ")";
    for (const auto& ring : arena.rings()) {
      std::vector<XY> pts;
      for (const auto& v : ring) pts.emplace_back(v[0], v[1]);
      p.rings.push_back(std::move(pts));
    }
    // Every 8th point (a step is 0.04 units), keeping the points around a jump.
    const auto thin = [](const std::vector<kernel::FxPoint>& pts) {
      std::vector<XY> out;
      for (std::size_t i = 0; i < pts.size(); ++i)
        if (i % 8 == 0 || i + 1 == pts.size())
          out.emplace_back(geometry::to_double(pts[i].x), geometry::to_double(pts[i].y));
      return out;
    };
    p.trail1 = thin(r.trail1);
    p.trail2 = thin(r.trail2);
    panels.push_back(std::move(p));
  }
  save_trails_figure("Paper 000, Figure 4: two visits' trails in three circles",
                     "Trial 0 of each circle, 50 000 steps per visit, trail width 0.1 (unit: the "
                     "robot's diameter).\nIn the smallest circle the trails cover the floor and "
                     "blend: crossings are undercounted there.",
                     panels, w.out() / "buffon/figure4.svg", w.out() / "buffon/figure4.png");
  w.added("buffon/figure4.svg");
  w.added("buffon/figure4.png");
}

// The fewest and the most trials of a figure's arenas (--decide extends only the arenas its
// undecided parts read).
std::pair<std::int64_t, std::int64_t> fewest_most(const BuffonFigure& f) {
  std::pair<std::int64_t, std::int64_t> n{f.params.trials, 0};
  for (const auto& r : f.rows) n = {std::min(n.first, r.trials), std::max(n.second, r.trials)};
  return f.rows.empty() ? std::pair{f.params.trials, f.params.trials} : n;
}

// Paper 000's trials per arena in words: one count, or each figure's when --decide ran them to
// different counts ("400 to 12800" where its arenas differ).
std::string buffon_trials_text(const BuffonResults& buffon) {
  std::map<int, std::pair<std::int64_t, std::int64_t>> counts; // fewest, most
  for (const auto& [figure, f] : buffon.figures) counts[figure] = fewest_most(f);
  counts[14] = {buffon.fig14.params.trials, buffon.fig14.params.trials};
  bool same = true;
  for (const auto& [figure, n] : counts) same = same && n == counts.begin()->second;
  const auto text_of = [](std::pair<std::int64_t, std::int64_t> n) {
    return n.first == n.second ? std::to_string(n.first)
                               : std::to_string(n.first) + " to " + std::to_string(n.second);
  };
  if (same) return text_of(counts.begin()->second) + " trials per arena";
  std::string text = "trials per arena by figure (";
  for (const auto& [figure, n] : counts)
    text += (figure == counts.begin()->first ? "" : ", ") + std::string("Figure ") +
            std::to_string(figure) + ": " + text_of(n);
  return text + ")";
}

const char* const kCaptions[] = {"Figure 5: circles and squares", "Figure 6: compactness",
                                 "Figure 7: barriers", "Figure 8: holes and obstacles",
                                 "Figure 9: trail width"};

class Paper000 final : public PaperRun {
public:
  explicit Paper000(const ReproduceOptions& o) : seed_(o.seed) {
    for (const int figure : {5, 6, 7, 8, 9}) {
      BuffonFigureParams p;
      p.figure = figure;
      p.seed = o.seed;
      trials_.emplace(figure, BuffonFigureTrials(p));
    }
    BuffonFigureParams p14;
    p14.figure = 14;
    p14.seed = o.seed;
    fig14_.emplace(p14);
  }
  [[nodiscard]] std::vector<std::string> units() const override {
    return {"buffon/figure5", "buffon/figure6", "buffon/figure7",
            "buffon/figure8", "buffon/figure9", "buffon/figure14"};
  }
  // Each claim reads one figure: its experiment, "buffon/figureN.csv".
  [[nodiscard]] std::string unit_of(const ClaimSpec& spec) const override {
    const std::string experiment = spec.experiment;
    return experiment.substr(0, experiment.rfind('.'));
  }
  void run(const std::string& unit, const Trials& trials, int,
           const algorithms::Runner& runner) override {
    const int figure = std::stoi(unit.substr(std::string("buffon/figure").size()));
    if (figure == 14) {
      fig14_->extend(trials.buffon, runner);
      if (runner.root()) results_.fig14 = fig14_->finish();
      return;
    }
    auto& t = trials_.at(figure);
    // The arenas this run extends: those narrow() kept (rank 0's word, so that every rank runs
    // the same units), or all of them.
    const auto kept = narrowed_.find(unit);
    std::vector<bool> arenas(t.arenas());
    std::size_t count = 0;
    for (std::size_t k = 0; k < arenas.size(); ++k) {
      arenas[k] = runner.any(runner.root() && (kept == narrowed_.end() || kept->second.at(k)));
      count += arenas[k] ? std::size_t{1} : std::size_t{0};
    }
    if (kept != narrowed_.end()) narrowed_.erase(kept);
    last_arenas_[unit] = count;
    extended_[unit] = arenas;
    t.extend(trials.buffon, arenas, runner);
    if (runner.root()) results_.figures[figure] = t.finish();
  }
  // Whether `unit`'s last run extended every row these parts read (rows_read); Figure 14 always
  // runs whole.
  [[nodiscard]] bool fresh(const std::string& unit, const std::vector<Part>& parts) const override {
    const auto ran = extended_.find(unit);
    const int figure = std::stoi(unit.substr(std::string("buffon/figure").size()));
    if (figure == 14 || ran == extended_.end()) return true;
    const auto read = rows_read(figure, parts);
    if (!read) return false;
    for (std::size_t k = 0; k < read->size(); ++k)
      if ((*read)[k] && !(k < ran->second.size() && ran->second[k])) return false;
    return true;
  }
  [[nodiscard]] std::string narrowed_text(const std::string& unit) const override {
    const auto kept = narrowed_.find(unit);
    if (kept == narrowed_.end()) return {};
    return std::to_string(std::count(kept->second.begin(), kept->second.end(), true)) + " of " +
           std::to_string(kept->second.size()) + " arenas";
  }
  // A figure's next run extends only the arenas whose trials the undecided parts resample
  // (rows_read); a part it cannot place keeps the whole figure, and Figure 14 always runs whole
  // (its calibration reads every circle).
  double narrow(const std::string& unit, const std::vector<Part>& undecided) override {
    narrowed_.erase(unit);
    const int figure = std::stoi(unit.substr(std::string("buffon/figure").size()));
    if (figure == 14 || undecided.empty()) return 1.0;
    auto keep = rows_read(figure, undecided);
    if (!keep) return 1.0;
    const auto kept = static_cast<double>(std::count(keep->begin(), keep->end(), true));
    const auto last =
        last_arenas_.count(unit) > 0 ? last_arenas_.at(unit) : trials_.at(figure).arenas();
    narrowed_[unit] = std::move(*keep);
    return last > 0 ? kept / static_cast<double>(last) : 1.0;
  }
  void inputs(ClaimInputs& in) const override { in.put(results_); }
  [[nodiscard]] std::string trials_text(const Trials& t, int) const override {
    return std::to_string(t.buffon) + " trials per arena";
  }
  [[nodiscard]] std::string counts_text() const override {
    return buffon_trials_text(results_) + " for paper 000 (the paper: 100)";
  }
  void counts_json(std::vector<std::pair<std::string, std::int64_t>>& counts) const override {
    for (const auto& [figure, f] : results_.figures)
      counts.emplace_back("buffon_figure" + std::to_string(figure) + "_per_arena", f.params.trials);
    counts.emplace_back("buffon_figure14_per_arena", results_.fig14.params.trials);
  }
  void write(ReportFiles& w, const ReproduceOptions& options, std::ostream& body,
             std::vector<ExperimentRecord>& records) const override {
    w.dir("buffon");
    buffon_figure4(w, seed_);
    body << "## Paper 000: Buffon's-needle area measurement\n\n"
         << buffon_trials_text(results_) << " (the paper: 100), 50 000 steps per visit, trail "
         << "width 0.1 unless the figure varies it. nBC is the Buffon count per unit length of "
            "visit 2; efficiency is nBC pi A / (2 L1), 1 for an ideal needle count. The paper "
            "gives no numbers for these figures, only statements (section 6), which the claims "
            "above test.\n\n"
         << "### Figure 4: trails\n\n"
         << report_image("buffon/figure4", "Figure 4: trails in three circles");
    for (const auto& [figure, f] : results_.figures) {
      const std::string stem = "buffon/figure" + std::to_string(figure);
      const char* caption = kCaptions[figure - 5];
      w.text(stem + ".csv", buffon_figure_csv(f));
      w.figure(stem, buffon_figure_plot(f));
      body << "### " << caption << "\n\n" << report_image(stem, caption);
      if (figure == 5) {
        w.figure("buffon/figure5b", buffon_figure5b_plot(f));
        body << report_image("buffon/figure5b", "Figure 5b: squares against circles");
      }
      body << buffon_rows_table(f) << '\n';
      const auto [fewest, most] = fewest_most(f);
      records.push_back({"paper 000, figure " + std::to_string(figure), f.hash,
                         fewest == most
                             ? "antkit buffon-experiment --figure " + std::to_string(figure) +
                                   " --trials " + std::to_string(f.params.trials) + " --seed " +
                                   std::to_string(seed_) + " --out DIR (prints this hash)"
                             : reproduce_command(options, {"buffon"}) +
                                   " (its arenas ran to different counts, the CSV's trials "
                                   "column; each arena's trials are those of `antkit "
                                   "buffon-experiment --trials` at its count)"});
    }
    const auto& fig14 = results_.fig14;
    w.text("buffon/figure14.csv", figure14_csv(fig14));
    w.figure("buffon/figure14", figure14_plot(fig14));
    body << "### Figure 14: calibrated Buffon against Random Search\n\n"
         << report_image("buffon/figure14", "Figure 14")
         << "Rows: buffon/figure14.csv (medians and interquartile ranges per circle and "
            "checkpoint, with the fit a + b nBC^c).\n\n";
    records.push_back({"paper 000, figure 14", fig14.hash,
                       "antkit buffon-experiment --figure 14 --trials " +
                           std::to_string(fig14.params.trials) + " --seed " +
                           std::to_string(seed_) + " --out DIR (prints this hash)"});
  }

private:
  // The rows of Figure `figure` (5-9) whose trials these parts resample: a part's samples are
  // rows' per-trial vectors (nBC, visit-1 length or BC), so the rows are found by comparing them.
  // None when a part has no samples or one no row holds (derived from several), or the figure has
  // not run (rank 0's results).
  [[nodiscard]] std::optional<std::vector<bool>> rows_read(int figure,
                                                           const std::vector<Part>& parts) const {
    const auto found = results_.figures.find(figure);
    if (found == results_.figures.end()) return std::nullopt;
    const auto& rows = found->second.rows;
    if (rows.size() != trials_.at(figure).arenas()) return std::nullopt;
    std::vector<bool> read(rows.size(), false);
    for (const auto& part : parts) {
      if (part.samples.empty()) return std::nullopt;
      for (const auto& sample : part.samples) {
        bool matched = false;
        for (std::size_t k = 0; k < rows.size(); ++k)
          if (sample == rows[k].nbc_trials || sample == rows[k].length1_trials ||
              sample == rows[k].bc_trials)
            read[k] = matched = true;
        if (!matched) return std::nullopt;
      }
    }
    return read;
  }

  std::uint64_t seed_;
  std::map<int, BuffonFigureTrials> trials_;
  std::map<std::string, std::vector<bool>> narrowed_; // the next run's arenas (rank 0)
  std::map<std::string, std::size_t> last_arenas_;    // how many arenas each unit's last run ran
  std::map<std::string, std::vector<bool>> extended_; // which arenas each unit's last run ran
  std::optional<Figure14Trials> fig14_;
  BuffonResults results_;
};

} // namespace

PaperEntry paper_000_entry() {
  return {"000", "buffon", &claims_000,
          [](const ReproduceOptions& o) { return std::make_unique<Paper000>(o); }};
}

} // namespace antkit::experiments
