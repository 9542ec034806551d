// Paper 002 in a reproduction (papers.hpp): every STC variant's audited tours on the shared and
// keyed random maps, the marker-noise curve, and the robot on its floor; one unit rerun whole at
// each look.
#include <antkit/experiments/drawing.hpp>
#include <antkit/experiments/format.hpp>
#include <antkit/experiments/papers.hpp>
#include <antkit/experiments/stc_floor.hpp>
#include <antkit/experiments/stc_tours.hpp>
#include <antkit/stc/world.hpp>

namespace antkit::experiments {

namespace {

// Paper 002's robot on its floor (the rendered floor, camera and pilot of devices/stc_floor,
// experiments/stc_floor.hpp), for the two claims on its hardware: a weakening battery's turn
// drift (2 000 ppm a minute, the first level of results/stc_floor's curve) with the paper's
// rotation calibration and without, on the same keyed boards; and the largest open board that
// closes when the marks fade as the paper's camera saw them (a 30 s half-life: lost after about
// 70 s, "the first minute or so"), boards of 2 x 2 to 4 x 4 cells.
FloorParams floor_params_of(const Trials& trials, std::uint64_t seed) {
  FloorParams floor_params;
  floor_params.trials = trials.stc_floor_boards;
  floor_params.seed = seed;
  floor_params.noise = {};
  floor_params.fade_s = {};
  floor_params.drift = {2000};
  floor_params.board_fade_s = {30};
  floor_params.max_board = 4;
  return floor_params;
}

class Paper002 final : public PaperRun {
public:
  explicit Paper002(const ReproduceOptions& o) : seed_(o.seed) {
    params_.maps_dir = o.maps_dir;
    params_.seed = o.seed;
  }
  [[nodiscard]] std::vector<std::string> units() const override { return {"stc"}; }
  void run(const std::string&, const Trials& trials, int,
           const algorithms::Runner& runner) override {
    trials_ = trials;
    params_.random_maps = trials.stc_random_maps;
    params_.noise_trials = trials.stc_noise_trials;
    stc_ = run_stc_tours(params_, runner);
    floor_ = run_floor_curves(floor_params_of(trials, seed_), runner);
  }
  void inputs(ClaimInputs& in) const override {
    in.put(stc_);
    in.put(floor_);
  }
  [[nodiscard]] std::string trials_text(const Trials& t, int) const override {
    return std::to_string(t.stc_random_maps) + " random maps, " +
           std::to_string(t.stc_noise_trials) + " noisy trials, " +
           std::to_string(t.stc_floor_boards) + " floor boards";
  }
  [[nodiscard]] std::string counts_text() const override {
    return std::to_string(trials_.stc_random_maps) + " random maps, " +
           std::to_string(trials_.stc_noise_trials) + " noisy trials per level and " +
           std::to_string(trials_.stc_floor_boards) + " floor boards per condition for paper 002";
  }
  void counts_json(std::vector<std::pair<std::string, std::int64_t>>& counts) const override {
    counts.emplace_back("stc_random_maps", trials_.stc_random_maps);
    counts.emplace_back("stc_noise_trials", trials_.stc_noise_trials);
    counts.emplace_back("stc_floor_boards", trials_.stc_floor_boards);
  }
  void write(ReportFiles& w, const ReproduceOptions& options, std::ostream& body,
             std::vector<ExperimentRecord>& records) const override {
    w.dir("stc");
    w.text("stc/tours.csv", stc_tours_csv(stc_));
    w.text("stc/noise.csv", stc_noise_csv(stc_));
    if (!stc_.noise.empty()) w.figure("stc/noise", stc_noise_plot(stc_));
    body << "## Paper 002: ant-like Spanning Tree Coverage\n\n"
         << "Every variant on " << stc_.maps.size() << " maps ("
         << (stc_.maps.size() > static_cast<std::size_t>(trials_.stc_random_maps)
                 ? "the shared MovingAI maps and "
                 : "no shared maps found; ")
         << trials_.stc_random_maps
         << " keyed random maps of 64 x 64 sub-cells with 10 % blocked), from the start `antkit "
            "stc` takes, each tour audited by `antkit check stc` (antkit::testing). The paper "
            "reports no numbers: its claim is the task itself.\n\n"
         << "| variant | tours | pass | sub-cells covered (sum) | repeats (sum) |\n"
            "|---|---|---|---|---|\n";
    for (const auto v : stc::kVariants) {
      std::size_t count = 0, pass = 0;
      std::int64_t covered = 0, repeats = 0;
      for (const auto& r : stc_.tours)
        if (r.variant == stc::variant_name(v))
          ++count, pass += r.audit_ok, covered += r.covered, repeats += r.repeats;
      body << "| " << stc::variant_name(v) << " | " << count << " | " << pass << " | " << covered
           << " | " << repeats << " |\n";
    }
    body << "\nEvery tour: stc/tours.csv.\n\n";
    // A tour on a real map (den312d when present, else the first map).
    std::string tour_map = stc_.maps.empty() ? "" : stc_.maps.front();
    for (const auto& m : stc_.maps)
      if (m == "den312d.map") tour_map = m;
    if (!tour_map.empty()) {
      const auto grid = stc_experiment_map(params_, tour_map);
      if (const auto start = stc::default_start(grid, stc::Variant::AntEdge)) {
        const auto r = stc::run_stc(grid, *start, stc::Variant::AntEdge);
        save_tour_figure(
            grid, r.path, "Paper 002: ant-edge STC on " + tour_map,
            std::to_string(r.reachable_subcells) + " reachable sub-cells, " +
                std::to_string(r.covered) + " covered, " + std::to_string(r.repeats) +
                " repeats, back at the start cell: " + (r.returned_to_start ? "yes" : "no") + ".",
            w.out() / "stc/tour.svg", w.out() / "stc/tour.png");
        w.added("stc/tour.svg");
        w.added("stc/tour.png");
        body << "### A tour on a real map\n\n" << report_image("stc/tour", "ant-edge tour");
      }
    }
    if (!stc_.noise.empty()) {
      body << "### Marker noise (ours; the paper gives no curve)\n\n"
           << report_image("stc/noise", "marker noise curve")
           << "| variant | misread probability | coverage | repeats per sub-cell | complete tours "
              "|\n|---|---|---|---|---|\n";
      for (const auto& p : stc_.noise)
        body << "| " << p.variant << " | " << number(p.ppm / 1e6) << " | " << fixed(p.coverage, 4)
             << " | " << fixed(p.repeats_per_subcell, 4) << " | " << fixed(p.complete, 2) << " |\n";
      body << '\n';
    }
    w.text("stc/floor_curves.csv", floor_curves_csv(floor_));
    w.text("stc/floor_boards.csv", floor_boards_csv(floor_));
    body << "### The robot on its floor\n\n"
         << "Paper 002's robot driving ant-edge STC through its rendered camera "
            "(experiments/stc_floor.hpp; the whole study is `antkit stc-floor-experiment`, "
            "results/stc_floor/): "
         << trials_.stc_floor_boards
         << " keyed boards of 8 x 8 cells with 10 % of their sub-cells blocked, at a turn drift "
            "of 2 000 ppm a minute with the paper's rotation calibration and without "
            "(stc/floor_curves.csv); open boards of 2 x 2 to 4 x 4 cells with marks of a 30 s "
            "half-life (stc/floor_boards.csv).\n\n";
    records.push_back(
        {"paper 002, tours and marker noise", stc_.hash, reproduce_command(options, {"stc"})});
    records.push_back(
        {"paper 002, the robot on its floor", floor_.hash, reproduce_command(options, {"stc"})});
  }

private:
  std::uint64_t seed_;
  Trials trials_;
  StcToursParams params_;
  StcTours stc_;
  FloorCurves floor_;
};

} // namespace

PaperEntry paper_002_entry() {
  return {"002", "stc", &claims_002,
          [](const ReproduceOptions& o) { return std::make_unique<Paper002>(o); }};
}

} // namespace antkit::experiments
