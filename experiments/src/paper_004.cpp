// Paper 004 in a reproduction (papers.hpp): Tables 1-4 with the line-of-sight sensor and with a
// disk sensor; one unit rerun whole at each look.
#include <antkit/experiments/format.hpp>
#include <antkit/experiments/papers.hpp>
#include <antkit/experiments/uniform_tables.hpp>
#include <antkit/kernel/hash.hpp>

namespace antkit::experiments {

namespace {

namespace ut = uniform_tables;

class Paper004 final : public PaperRun {
public:
  explicit Paper004(const ReproduceOptions& o) : seed_(o.seed) {
    config_.seed = o.seed;
    disk_config_ = config_;
    disk_config_.sensor_model = uniform::SensorModel::Disk;
  }
  [[nodiscard]] std::vector<std::string> units() const override { return {"uniform"}; }
  void run(const std::string&, const Trials& trials, int,
           const algorithms::Runner& runner) override {
    config_.runs = static_cast<std::uint32_t>(trials.uniform_runs);
    disk_config_.runs = config_.runs;
    results_.rows = ut::run_tables(config_, runner);
    results_.disk = ut::run_tables(disk_config_, runner);
    results_.runs = config_.runs;
  }
  void inputs(ClaimInputs& in) const override { in.put(results_); }
  [[nodiscard]] std::string trials_text(const Trials& t, int) const override {
    return std::to_string(t.uniform_runs) + " runs per row";
  }
  [[nodiscard]] std::string counts_text() const override {
    return std::to_string(config_.runs) + " runs per row for paper 004 (the paper: 10)";
  }
  void counts_json(std::vector<std::pair<std::string, std::int64_t>>& counts) const override {
    counts.emplace_back("uniform_runs_per_row", config_.runs);
  }
  void write(ReportFiles& w, const ReproduceOptions&, std::ostream& body,
             std::vector<ExperimentRecord>& records) const override {
    const auto& rows = results_.rows;
    const auto& disk = results_.disk;
    w.dir("uniform");
    w.dir("uniform/disk");
    w.text("uniform/uniform_tables.csv", ut::tables_csv(rows, config_));
    w.text("uniform/uniform_tables.md", ut::tables_markdown(rows, config_));
    w.text("uniform/disk/uniform_tables.csv", ut::tables_csv(disk, disk_config_));
    w.text("uniform/disk/uniform_tables.md", ut::tables_markdown(disk, disk_config_));
    w.figure("uniform/coverage", ut::tables_plot(rows, config_));
    body << "## Paper 004: uniform coverage (RW, PM, A*)\n\n"
         << embed_markdown(ut::tables_markdown(rows, config_))
         << "\n### Coverage against movements\n\n"
         << report_image("uniform/coverage", "coverage against movements")
         << "### The disk-sensor test\n\nThe same runs with a sensor that views every cell within "
            "range, through walls (RW, PM and A* only): uniform/disk/uniform_tables.md. PM's "
            "coverage per row, line of sight / disk / the paper's:\n\n"
            "| density % | robots | PM, line of sight | PM, disk | PM, paper "
            "|\n|---|---|---|---|---|\n";
    for (std::size_t i = 0; i < rows.size() && i < disk.size(); ++i)
      body << "| " << rows[i].paper->density_percent << " | " << rows[i].paper->robots << " | "
           << fixed(rows[i].coverage[1], 2) << " | " << fixed(disk[i].coverage[1], 2) << " | "
           << fixed(rows[i].paper->coverage[1], 2) << " |\n";
    body << '\n';
    kernel::TraceHash los_digest, disk_digest;
    for (const auto& r : rows) los_digest.add_u64(r.hash);
    for (const auto& r : disk) disk_digest.add_u64(r.hash);
    records.push_back({"paper 004, tables 1-4", los_digest.finish(),
                       "antkit cover-experiment --runs " + std::to_string(config_.runs) +
                           " --seed " + std::to_string(seed_) + " --out DIR (prints this hash)"});
    records.push_back({"paper 004, tables 1-4, disk sensor", disk_digest.finish(),
                       "antkit cover-experiment --runs " + std::to_string(config_.runs) +
                           " --seed " + std::to_string(seed_) +
                           " --sensor-model disk --out DIR (prints this hash)"});
  }

private:
  std::uint64_t seed_;
  ut::TablesConfig config_, disk_config_;
  UniformResults results_;
};

} // namespace

PaperEntry paper_004_entry() {
  return {"004", "uniform", &claims_004,
          [](const ReproduceOptions& o) { return std::make_unique<Paper004>(o); }};
}

} // namespace antkit::experiments
