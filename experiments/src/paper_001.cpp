// Paper 001 in a reproduction (papers.hpp): Tables 2-3 and Figures 4-6, one unit rerun whole at
// each look (the paper's repetitions times the look's factor: well under a second at 10).
#include <antkit/experiments/drawing.hpp>
#include <antkit/experiments/explore_tables.hpp>
#include <antkit/experiments/papers.hpp>

namespace antkit::experiments {

namespace {

class Paper001 final : public PaperRun {
public:
  explicit Paper001(const ReproduceOptions& o) : seed_(o.seed) {}
  [[nodiscard]] std::vector<std::string> units() const override { return {"los"}; }
  void run(const std::string&, const Trials&, int factor,
           const algorithms::Runner& runner) override {
    tables_ = run_explore_tables(seed_, runner, factor);
    factor_ = factor;
  }
  void inputs(ClaimInputs& in) const override { in.put(tables_); }
  [[nodiscard]] std::string trials_text(const Trials&, int factor) const override {
    return std::to_string(10 * factor) + " repetitions per environment (" +
           std::to_string(5 * factor) + " for the blocks)";
  }
  [[nodiscard]] std::string counts_text() const override {
    return factor_ == 1 ? "paper 001's own repetitions"
                        : trials_text({}, factor_) + " for paper 001 (the paper: 10, 5)";
  }
  void counts_json(std::vector<std::pair<std::string, std::int64_t>>& counts) const override {
    counts.emplace_back("los_repetitions", 10 * factor_);
  }
  void write(ReportFiles& w, const ReproduceOptions& options, std::ostream& body,
             std::vector<ExperimentRecord>& records) const override {
    w.dir("los");
    w.text("los/table2.csv", table2_csv(tables_));
    w.text("los/table2.md", table2_markdown(tables_));
    w.text("los/table3.csv", table3_csv(tables_));
    w.text("los/table3.md", table3_markdown(tables_));
    w.figure("los/figures5-6", explore_plot(tables_));
    explore_stages_figure(seed_, w.out() / "los/figure4.svg", w.out() / "los/figure4.png");
    w.added("los/figure4.svg");
    w.added("los/figure4.png");
    body << "## Paper 001: two-robot line-of-sight exploration\n\n"
         << "25 x 25 cells, "
         << (factor_ == 1 ? std::string("the paper's 10 repetitions (5 for the blocks)")
                          : trials_text({}, factor_) + " (the paper: 10, 5 for the blocks; "
                                                       "Table 2 lists the first 10)")
         << " per environment, seed " << seed_
         << ". \"Sheng et al.\" (ours) is the frontier baseline as paper 001 describes it: "
            "g = w1 I - w2 D + w3 lambda with w1 = w2 = 1, w3 = 0, and the information gain I "
            "counting only the cells outside the other robot's sensor range and target, without "
            "line-of-sight sweeping; the strong baseline is the same with sweeping. Each cell: "
            "ours / the paper's.\n\n"
         << "### Figure 4: stages of one run\n\n"
         << report_image("los/figure4", "Figure 4: stages of one run") << "### Table 2\n\n"
         << embed_markdown(table2_markdown(tables_)) << "\n### Table 3\n\n"
         << embed_markdown(table3_markdown(tables_)) << "\n### Figures 5-6\n\n"
         << report_image("los/figures5-6", "Figures 5-6: steps and E.M.E");
    records.push_back({"paper 001, tables 2-3", tables_.hash,
                       factor_ == 1 ? "antkit explore-tables --seed " + std::to_string(seed_) +
                                          " --out DIR --format json (prints this hash)"
                                    : reproduce_command(options, {"los"})});
  }

private:
  std::uint64_t seed_;
  int factor_ = 1;
  ExploreTables tables_;
};

} // namespace

PaperEntry paper_001_entry() {
  return {"001", "los", &claims_001,
          [](const ReproduceOptions& o) { return std::make_unique<Paper001>(o); }};
}

} // namespace antkit::experiments
