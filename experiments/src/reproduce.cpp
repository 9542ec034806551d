#include <algorithm>
#include <antkit/buffon/measurement.hpp>
#include <antkit/experiments/buffon_figures.hpp>
#include <antkit/experiments/claims.hpp>
#include <antkit/experiments/drawing.hpp>
#include <antkit/experiments/explore_tables.hpp>
#include <antkit/experiments/format.hpp>
#include <antkit/experiments/reproduce.hpp>
#include <antkit/experiments/stc_tours.hpp>
#include <antkit/experiments/uniform_tables.hpp>
#include <antkit/geometry/arena_spec.hpp>
#include <antkit/geometry/fixed_convert.hpp>
#include <antkit/io/atomic_file.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/world.hpp>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

namespace antkit::experiments {

namespace ut = antkit::experiments::uniform_tables;
using kernel::InputError;

namespace {

const std::vector<std::string> kFamilies = {"buffon", "los", "stc", "uniform"};

// The output directory, its subdirectories, and the files written (relative paths).
class Writer {
public:
  explicit Writer(std::filesystem::path out) : out_(std::move(out)) {}
  void dir(const std::string& sub) {
    std::error_code ec;
    std::filesystem::create_directories(out_ / sub, ec);
    if (!std::filesystem::is_directory(out_ / sub))
      throw InputError("output directory",
                       "cannot make the directory '" + (out_ / sub).string() + "'");
  }
  void text(const std::string& rel_path, const std::string& content) {
    io::write_file_atomic(out_ / rel_path, content);
    files_.emplace_back(rel_path);
  }
  void figure(const std::string& stem, const Figure& f) {
    save_figure(f, out_ / (stem + ".svg"), out_ / (stem + ".png"));
    files_.emplace_back(stem + ".svg");
    files_.emplace_back(stem + ".png");
  }
  [[nodiscard]] const std::filesystem::path& out() const { return out_; }
  void added(const std::string& rel_path) { files_.emplace_back(rel_path); }
  [[nodiscard]] const std::vector<std::filesystem::path>& files() const { return files_; }

private:
  std::filesystem::path out_;
  std::vector<std::filesystem::path> files_;
};

// A Markdown file's body under the report's own heading level: its first "# " title dropped and
// every other heading two levels deeper.
std::string embed(const std::string& md) {
  std::istringstream in(md);
  std::ostringstream out;
  std::string line;
  bool first = true;
  while (std::getline(in, line)) {
    if (first && line.rfind("# ", 0) == 0) {
      first = false;
      continue;
    }
    first = false;
    if (line.rfind("#", 0) == 0) line = "##" + line;
    out << line << '\n';
  }
  return out.str();
}

nlohmann::json parts_json(const std::vector<ClaimPart>& parts) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : parts)
    out.push_back({{"label", p.label},
                   {"value", p.value},
                   {"interval", {p.ci.lo, p.ci.hi}},
                   {"level", p.level},
                   {"method", p.method},
                   {"rule", p.rule},
                   {"verdict", verdict_text(p.verdict)}});
  return out;
}

std::string image(const std::string& stem, const std::string& alt) {
  return "![" + alt + "](" + stem + ".png)\n\n(" + stem + ".svg, " + stem + ".png)\n\n";
}

// ---------------------------------------------------------------------------------------------
// Paper 000.

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
void buffon_figure4(Writer& w, std::uint64_t seed) {
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

} // namespace

Trials trials_of(Scale scale) {
  if (scale == Scale::Full) return {};
  return {20, 3, 6, 10, 4};
}

void validate(const ReproduceOptions& options) {
  for (const auto& name : options.only)
    if (std::find(kFamilies.begin(), kFamilies.end(), name) == kFamilies.end())
      throw InputError("families", "'" + name + "' is not one of buffon, los, stc, uniform");
}

std::string reproduce_command(const ReproduceOptions& o, const std::vector<std::string>& only) {
  std::string s =
      std::string("antkit reproduce ") + (o.scale == Scale::Full ? "--full" : "--quick");
  if (!only.empty()) {
    s += " --only ";
    for (std::size_t i = 0; i < only.size(); ++i) s += (i ? "," : "") + only[i];
  }
  s += " --seed " + std::to_string(o.seed);
  if (only.empty() || std::find(only.begin(), only.end(), "stc") != only.end())
    s += " --maps " + (o.maps_dir.empty() ? std::string("''") : o.maps_dir.string());
  return s + " --out DIR";
}

std::string claims_markdown(const std::vector<Claim>& claims) {
  // A '|' inside a cell would end it.
  const auto cell = [](const std::string& text) {
    std::string out;
    for (const char ch : text) out += ch == '|' ? std::string("\\|") : std::string(1, ch);
    return out;
  };
  std::ostringstream s;
  s << "| claim | paper | where | the paper says | verdict | measured | why (where it does not "
       "hold) |\n|---|---|---|---|---|---|---|\n";
  for (const auto& c : claims)
    s << "| " << c.id << " | " << c.paper << " | " << cell(c.source) << " | " << cell(c.text)
      << " | **" << verdict_text(c.verdict) << "** | " << cell(c.measured) << " | " << cell(c.why)
      << " |\n";
  return s.str();
}

ReproduceReport reproduce(const ReproduceOptions& o, const algorithms::Runner& runner) {
  validate(o);
  const auto wants = [&](const char* family) {
    return o.only.empty() || std::find(o.only.begin(), o.only.end(), family) != o.only.end();
  };
  const Trials trials = trials_of(o.scale);
  Writer w(o.out);
  if (runner.root())
    for (const char* family : {"buffon", "los", "stc", "uniform"})
      if (wants(family)) w.dir(family);
  if (runner.root() && wants("uniform")) w.dir("uniform/disk");
  ReproduceReport report;
  std::ostringstream md;
  const std::string scale = o.scale == Scale::Full ? "full" : "quick";

  // Paper 000.
  BuffonResults buffon;
  if (wants("buffon")) {
    for (const int figure : {5, 6, 7, 8, 9}) {
      BuffonFigureParams p;
      p.figure = figure;
      p.trials = trials.buffon;
      p.seed = o.seed;
      buffon.figures.emplace(figure, run_buffon_figure(p, runner));
    }
    BuffonFigureParams p14;
    p14.figure = 14;
    p14.trials = trials.buffon;
    p14.seed = o.seed;
    buffon.fig14 = run_figure14(p14, runner);
  }
  ExploreTables los;
  if (wants("los")) los = run_explore_tables(o.seed, runner);
  StcTours stc;
  StcToursParams stc_params;
  stc_params.maps_dir = o.maps_dir;
  stc_params.random_maps = trials.stc_random_maps;
  stc_params.noise_trials = trials.stc_noise_trials;
  stc_params.seed = o.seed;
  if (wants("stc")) stc = run_stc_tours(stc_params, runner);
  // Paper 002's robot on its floor (the rendered floor, camera and pilot of devices/stc_floor,
  // experiments/stc_floor.hpp), for the two claims on its hardware: a weakening battery's turn
  // drift (2 000 ppm a minute, the first level of results/stc_floor's curve) with the paper's
  // rotation calibration and without, on the same keyed boards; and the largest open board that
  // closes when the marks fade as the paper's camera saw them (a 30 s half-life: lost after about
  // 70 s, "the first minute or so"), boards of 2 x 2 to 4 x 4 cells.
  FloorParams floor_params;
  floor_params.trials = trials.stc_floor_boards;
  floor_params.seed = o.seed;
  floor_params.noise = {};
  floor_params.fade_s = {};
  floor_params.drift = {2000};
  floor_params.board_fade_s = {30};
  floor_params.max_board = 4;
  FloorCurves floor;
  if (wants("stc")) floor = run_floor_curves(floor_params, runner);
  ut::TablesConfig uc;
  uc.runs = static_cast<std::uint32_t>(trials.uniform_runs);
  uc.seed = o.seed;
  ut::TablesConfig disk_config = uc;
  disk_config.sensor_model = uniform::SensorModel::Disk;
  std::vector<ut::TablesRow> uniform_rows, disk_rows;
  if (wants("uniform")) {
    uniform_rows = ut::run_tables(uc, runner);
    disk_rows = ut::run_tables(disk_config, runner);
  }
  if (!runner.root()) return report;

  // Decide and write (rank 0).
  std::ostringstream body;
  if (wants("buffon")) {
    buffon_figure4(w, o.seed);
    body << "## Paper 000: Buffon's-needle area measurement\n\n"
         << trials.buffon << " trials per arena (the paper: 100), 50 000 steps per visit, trail "
         << "width 0.1 unless the figure varies it. nBC is the Buffon count per unit length of "
            "visit 2; efficiency is nBC pi A / (2 L1), 1 for an ideal needle count. The paper "
            "gives no numbers for these figures, only statements (section 6), which the claims "
            "above test.\n\n"
         << "### Figure 4: trails\n\n"
         << image("buffon/figure4", "Figure 4: trails in three circles");
    const char* captions[] = {"",
                              "",
                              "",
                              "",
                              "",
                              "Figure 5: circles and squares",
                              "Figure 6: compactness",
                              "Figure 7: barriers",
                              "Figure 8: holes and obstacles",
                              "Figure 9: trail width"};
    for (auto& [figure, f] : buffon.figures) {
      const std::string stem = "buffon/figure" + std::to_string(figure);
      w.text(stem + ".csv", buffon_figure_csv(f));
      w.figure(stem, buffon_figure_plot(f));
      body << "### " << captions[figure] << "\n\n" << image(stem, captions[figure]);
      if (figure == 5) {
        w.figure("buffon/figure5b", buffon_figure5b_plot(f));
        body << image("buffon/figure5b", "Figure 5b: squares against circles");
      }
      body << buffon_rows_table(f) << '\n';
      report.experiments.push_back({"paper 000, figure " + std::to_string(figure), f.hash,
                                    "antkit buffon-experiment --figure " + std::to_string(figure) +
                                        " --trials " + std::to_string(trials.buffon) + " --seed " +
                                        std::to_string(o.seed) + " --out DIR (prints this hash)"});
    }
    w.text("buffon/figure14.csv", figure14_csv(buffon.fig14));
    w.figure("buffon/figure14", figure14_plot(buffon.fig14));
    body << "### Figure 14: calibrated Buffon against Random Search\n\n"
         << image("buffon/figure14", "Figure 14")
         << "Rows: buffon/figure14.csv (medians and interquartile ranges per circle and "
            "checkpoint, with the fit a + b nBC^c).\n\n";
    report.experiments.push_back({"paper 000, figure 14", buffon.fig14.hash,
                                  "antkit buffon-experiment --figure 14 --trials " +
                                      std::to_string(trials.buffon) + " --seed " +
                                      std::to_string(o.seed) + " --out DIR (prints this hash)"});
  }
  if (wants("los")) {
    w.text("los/table2.csv", table2_csv(los));
    w.text("los/table2.md", table2_markdown(los));
    w.text("los/table3.csv", table3_csv(los));
    w.text("los/table3.md", table3_markdown(los));
    w.figure("los/figures5-6", explore_plot(los));
    explore_stages_figure(o.seed, o.out / "los/figure4.svg", o.out / "los/figure4.png");
    w.added("los/figure4.svg");
    w.added("los/figure4.png");
    body << "## Paper 001: two-robot line-of-sight exploration\n\n"
         << "25 x 25 cells, the paper's 10 repetitions (5 for the blocks) per environment, seed "
         << o.seed
         << ". \"Sheng et al.\" (ours) is the frontier baseline as paper 001 describes it: "
            "g = w1 I - w2 D + w3 lambda with w1 = w2 = 1, w3 = 0, and the information gain I "
            "counting only the cells outside the other robot's sensor range and target, without "
            "line-of-sight sweeping; the strong baseline is the same with sweeping. Each cell: "
            "ours / the paper's.\n\n"
         << "### Figure 4: stages of one run\n\n"
         << image("los/figure4", "Figure 4: stages of one run") << "### Table 2\n\n"
         << embed(table2_markdown(los)) << "\n### Table 3\n\n"
         << embed(table3_markdown(los)) << "\n### Figures 5-6\n\n"
         << image("los/figures5-6", "Figures 5-6: steps and E.M.E");
    report.experiments.push_back({"paper 001, tables 2-3", los.hash,
                                  "antkit explore-tables --seed " + std::to_string(o.seed) +
                                      " --out DIR --format json (prints this hash)"});
  }
  if (wants("stc")) {
    w.text("stc/tours.csv", stc_tours_csv(stc));
    w.text("stc/noise.csv", stc_noise_csv(stc));
    if (!stc.noise.empty()) w.figure("stc/noise", stc_noise_plot(stc));
    body << "## Paper 002: ant-like Spanning Tree Coverage\n\n"
         << "Every variant on " << stc.maps.size() << " maps ("
         << (stc.maps.size() > static_cast<std::size_t>(trials.stc_random_maps)
                 ? "the shared MovingAI maps and "
                 : "no shared maps found; ")
         << trials.stc_random_maps
         << " keyed random maps of 64 x 64 sub-cells with 10 % blocked), from the start `antkit "
            "stc` takes, each tour audited by `antkit check stc` (antkit::testing). The paper "
            "reports no numbers: its claim is the task itself.\n\n"
         << "| variant | tours | pass | sub-cells covered (sum) | repeats (sum) |\n"
            "|---|---|---|---|---|\n";
    for (const auto v : stc::kVariants) {
      std::size_t count = 0, pass = 0;
      std::int64_t covered = 0, repeats = 0;
      for (const auto& r : stc.tours)
        if (r.variant == stc::variant_name(v))
          ++count, pass += r.audit_ok, covered += r.covered, repeats += r.repeats;
      body << "| " << stc::variant_name(v) << " | " << count << " | " << pass << " | " << covered
           << " | " << repeats << " |\n";
    }
    body << "\nEvery tour: stc/tours.csv.\n\n";
    // A tour on a real map (den312d when present, else the first map).
    std::string tour_map = stc.maps.empty() ? "" : stc.maps.front();
    for (const auto& m : stc.maps)
      if (m == "den312d.map") tour_map = m;
    if (!tour_map.empty()) {
      const auto grid = stc_experiment_map(stc_params, tour_map);
      if (const auto start = stc::default_start(grid, stc::Variant::AntEdge)) {
        const auto r = stc::run_stc(grid, *start, stc::Variant::AntEdge);
        save_tour_figure(
            grid, r.path, "Paper 002: ant-edge STC on " + tour_map,
            std::to_string(r.reachable_subcells) + " reachable sub-cells, " +
                std::to_string(r.covered) + " covered, " + std::to_string(r.repeats) +
                " repeats, back at the start cell: " + (r.returned_to_start ? "yes" : "no") + ".",
            o.out / "stc/tour.svg", o.out / "stc/tour.png");
        w.added("stc/tour.svg");
        w.added("stc/tour.png");
        body << "### A tour on a real map\n\n" << image("stc/tour", "ant-edge tour");
      }
    }
    if (!stc.noise.empty()) {
      body << "### Marker noise (ours; the paper gives no curve)\n\n"
           << image("stc/noise", "marker noise curve")
           << "| variant | misread probability | coverage | repeats per sub-cell | complete tours "
              "|\n|---|---|---|---|---|\n";
      for (const auto& p : stc.noise)
        body << "| " << p.variant << " | " << number(p.ppm / 1e6) << " | " << fixed(p.coverage, 4)
             << " | " << fixed(p.repeats_per_subcell, 4) << " | " << fixed(p.complete, 2) << " |\n";
      body << '\n';
    }
    w.text("stc/floor_curves.csv", floor_curves_csv(floor));
    w.text("stc/floor_boards.csv", floor_boards_csv(floor));
    body << "### The robot on its floor\n\n"
         << "Paper 002's robot driving ant-edge STC through its rendered camera "
            "(experiments/stc_floor.hpp; the whole study is `antkit stc-floor-experiment`, "
            "results/stc_floor/): "
         << trials.stc_floor_boards
         << " keyed boards of 8 x 8 cells with 10 % of their sub-cells blocked, at a turn drift "
            "of 2 000 ppm a minute with the paper's rotation calibration and without "
            "(stc/floor_curves.csv); open boards of 2 x 2 to 4 x 4 cells with marks of a 30 s "
            "half-life (stc/floor_boards.csv).\n\n";
    report.experiments.push_back(
        {"paper 002, tours and marker noise", stc.hash, reproduce_command(o, {"stc"})});
    report.experiments.push_back(
        {"paper 002, the robot on its floor", floor.hash, reproduce_command(o, {"stc"})});
  }
  if (wants("uniform")) {
    w.text("uniform/uniform_tables.csv", ut::tables_csv(uniform_rows, uc));
    w.text("uniform/uniform_tables.md", ut::tables_markdown(uniform_rows, uc));
    w.text("uniform/disk/uniform_tables.csv", ut::tables_csv(disk_rows, disk_config));
    w.text("uniform/disk/uniform_tables.md", ut::tables_markdown(disk_rows, disk_config));
    w.figure("uniform/coverage", ut::tables_plot(uniform_rows, uc));
    body << "## Paper 004: uniform coverage (RW, PM, A*)\n\n"
         << embed(ut::tables_markdown(uniform_rows, uc)) << "\n### Coverage against movements\n\n"
         << image("uniform/coverage", "coverage against movements")
         << "### The disk-sensor test\n\nThe same runs with a sensor that views every cell within "
            "range, through walls (RW, PM and A* only): uniform/disk/uniform_tables.md. PM's "
            "coverage per row, line of sight / disk / the paper's:\n\n"
            "| density % | robots | PM, line of sight | PM, disk | PM, paper "
            "|\n|---|---|---|---|---|\n";
    for (std::size_t i = 0; i < uniform_rows.size() && i < disk_rows.size(); ++i)
      body << "| " << uniform_rows[i].paper->density_percent << " | "
           << uniform_rows[i].paper->robots << " | " << fixed(uniform_rows[i].coverage[1], 2)
           << " | " << fixed(disk_rows[i].coverage[1], 2) << " | "
           << fixed(uniform_rows[i].paper->coverage[1], 2) << " |\n";
    body << '\n';
    kernel::TraceHash los_digest, disk_digest;
    for (const auto& r : uniform_rows) los_digest.add_u64(r.hash);
    for (const auto& r : disk_rows) disk_digest.add_u64(r.hash);
    report.experiments.push_back({"paper 004, tables 1-4", los_digest.finish(),
                                  "antkit cover-experiment --runs " + std::to_string(uc.runs) +
                                      " --seed " + std::to_string(o.seed) +
                                      " --out DIR (prints this hash)"});
    report.experiments.push_back({"paper 004, tables 1-4, disk sensor", disk_digest.finish(),
                                  "antkit cover-experiment --runs " + std::to_string(uc.runs) +
                                      " --seed " + std::to_string(o.seed) +
                                      " --sensor-model disk --out DIR (prints this hash)"});
  }

  // Decide every claim of the papers that ran (claims_000.cpp ...), in the papers' order.
  ClaimInputs inputs;
  if (wants("buffon")) inputs.buffon = &buffon;
  if (wants("los")) inputs.los = &los;
  if (wants("stc")) {
    inputs.stc = &stc;
    inputs.floor = &floor;
  }
  if (wants("uniform")) {
    inputs.uniform = &uniform_rows;
    inputs.uniform_disk = &disk_rows;
    inputs.uniform_runs = uc.runs;
  }
  for (const auto* table : {&claims_000(), &claims_001(), &claims_002(), &claims_004()})
    for (const auto& spec : *table)
      if (wants(spec.family)) report.claims.push_back(evaluate(spec, inputs, o.seed));

  // The report.
  std::size_t holds = 0, partly = 0, not_held = 0, open = 0;
  for (const auto& c : report.claims)
    (c.verdict == Verdict::Holds         ? holds
     : c.verdict == Verdict::Partly      ? partly
     : c.verdict == Verdict::DoesNotHold ? not_held
                                         : open)++;
  md << "# The papers, reproduced by antkit\n\n"
     << "`" << reproduce_command(o, o.only) << "` (" << scale << " scale";
  if (o.scale == Scale::Quick)
    md << ": " << trials.buffon << " trials per arena for paper 000 (the paper: 100), "
       << trials.uniform_runs << " runs per row for paper 004 (the paper: 10), "
       << trials.stc_random_maps << " random maps, " << trials.stc_noise_trials
       << " noisy trials per level and " << trials.stc_floor_boards
       << " floor boards per condition for paper 002; paper 001 in full. `--full` runs the papers' "
          "counts";
  else
    md << ": the papers' trial counts";
  md << "). Every number below depends only on these options, not on the threads or the MPI "
        "ranks: the trials are the kernel's, bit-exact on every compiler and CPU that "
        "scripts/determinism.sh checks; the reductions (medians, means, Figure 14's fit) are "
        "floating point on the machine that writes the report.\n\n"
     << "## Claims\n\n"
     << report.claims.size() << " claims: " << holds << " hold, " << partly << " partly, "
     << not_held << " do not hold, " << open << " inconclusive at this trial count.\n\n"
     << "How to read a verdict. Each claim is one or more parts (an arena, a row, an "
        "environment...); each part is a figure with an interval and a rule that compares it with "
        "a threshold. The intervals are percentile bootstraps over the trials ("
     << kBootstrapResamples
     << " resamples, drawn from the kernel's keyed streams by seed, claim and part, so the "
        "report stays byte-identical), Clopper-Pearson intervals for a proportion of runs, or "
        "none for an exact figure (an invariant checked on every run). A claim's intervals hold "
        "together at 95 %: with m parts, each is at 1 - 0.05 / m (Bonferroni). A part holds when "
        "its interval is on the rule's side of the threshold, does not hold when it is on the "
        "other side, and is undecided when the interval contains the threshold. A claim holds "
        "when every part holds, does not hold when no part holds and every part is decided, is "
        "*partly* when at least one part holds and at least one does not (the one convention "
        "for every claim), and is *inconclusive at this trial count* otherwise: more trials "
        "would decide it"
     << (o.scale == Scale::Quick ? " (`--full` runs the papers' counts)" : "")
     << ". The measured column gives each part's figure [its interval] for claims of up to "
        "four parts, a count for longer ones; every part is listed under \"Claims in detail\" "
        "below.\n\n"
     << claims_markdown(report.claims) << "\nRules, and the papers' own words:\n\n";
  for (const auto& c : report.claims)
    md << "- " << c.id << ": " << c.rule << "."
       << (c.quote.empty() ? std::string(" (A claim of ours beside the paper.)")
                           : " The paper: \"" + c.quote + "\"")
       << " Reads " << c.experiment << ".\n";
  md << "\n## Claims in detail\n\n"
     << "Each part: its figure, the interval (method, level) and the rule.\n\n";
  for (const auto& c : report.claims) {
    md << "### " << c.id << ": " << verdict_text(c.verdict) << "\n\n"
       << "| part | figure [interval] | interval | rule | verdict |\n|---|---|---|---|---|\n";
    for (const auto& p : c.parts) {
      char level[32];
      std::snprintf(level, sizeof level, "%.2f %%", 100 * p.level);
      md << "| " << p.label << " | " << p.figure << " | " << p.method
         << (p.method == std::string("exact") ? std::string() : std::string(", ") + level) << " | "
         << p.rule << " | " << verdict_text(p.verdict) << " |\n";
    }
    md << '\n';
  }
  md << body.str() << "## Trace hashes\n\n"
     << "Each experiment's trace hash (every trial's, in trial order) and a command that "
        "reproduces it. This whole report: `"
     << reproduce_command(o, o.only) << "`.\n\n| experiment | hash | command |\n|---|---|---|\n";
  for (const auto& e : report.experiments)
    md << "| " << e.name << " | `" << kernel::hash_hex(e.hash) << "` | `" << e.command << "` |\n";

  nlohmann::json j;
  j["command"] = reproduce_command(o, o.only);
  j["scale"] = scale;
  j["seed"] = o.seed;
  j["trials"] = {{"buffon_per_arena", trials.buffon},
                 {"uniform_runs_per_row", trials.uniform_runs},
                 {"stc_random_maps", trials.stc_random_maps},
                 {"stc_noise_trials", trials.stc_noise_trials},
                 {"stc_floor_boards", trials.stc_floor_boards}};
  nlohmann::json claims = nlohmann::json::array();
  for (const auto& c : report.claims)
    claims.push_back({{"id", c.id},
                      {"paper", c.paper},
                      {"source", c.source},
                      {"claim", c.text},
                      {"rule", c.rule},
                      {"verdict", verdict_text(c.verdict)},
                      {"measured", c.measured},
                      {"why", c.why},
                      {"quote", c.quote},
                      {"experiment", c.experiment},
                      {"parts", parts_json(c.parts)}});
  j["claims"] = std::move(claims);
  nlohmann::json hashes = nlohmann::json::array();
  for (const auto& e : report.experiments)
    hashes.push_back(
        {{"experiment", e.name}, {"hash", kernel::hash_hex(e.hash)}, {"command", e.command}});
  j["experiments"] = std::move(hashes);
  j["summary"] = {
      {"holds", holds}, {"partly", partly}, {"does_not_hold", not_held}, {"inconclusive", open}};
  j["intervals"] = {{"bootstrap_resamples", kBootstrapResamples},
                    {"family_level", 0.95},
                    {"per_part_level", "1 - 0.05 / m for a claim of m parts with intervals"}};
  w.text("claims.json", j.dump(2) + "\n");
  w.text("README.md", md.str());
  report.files = w.files();
  return report;
}

} // namespace antkit::experiments
