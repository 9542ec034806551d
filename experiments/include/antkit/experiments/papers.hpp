#pragma once
// The papers as data (issue 44): each paper `antkit reproduce` runs is one registered entry, its
// experiments (what a look reruns, and how), its claims table (claims.hpp), its files and figures
// and its report section; reproduce() is a loop over the entries. An entry lives in its paper's
// file, experiments/src/paper_NNN.cpp, as the function `PaperEntry paper_NNN_entry()`; the build
// lists those files (experiments/CMakeLists.txt generates the call of each), so adding a paper
// adds two files (paper_NNN.cpp and claims_NNN.cpp) and edits no shared list.
#include <antkit/algorithms/units.hpp>
#include <antkit/experiments/claims.hpp>
#include <antkit/experiments/plot.hpp>
#include <antkit/experiments/reproduce.hpp>
#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace antkit::experiments {

// The report's directory: its subdirectories and the files written (relative paths), each
// written atomically. Throws kernel::InputError("output directory", ...) for a directory that
// cannot be made.
class ReportFiles {
public:
  explicit ReportFiles(std::filesystem::path out) : out_(std::move(out)) {}
  void dir(const std::string& sub);
  void text(const std::string& rel_path, const std::string& content);
  void figure(const std::string& stem, const Figure& f); // stem.svg and stem.png
  void added(const std::string& rel_path) { files_.emplace_back(rel_path); } // written elsewhere
  [[nodiscard]] const std::filesystem::path& out() const { return out_; }
  [[nodiscard]] const std::vector<std::filesystem::path>& files() const { return files_; }

private:
  std::filesystem::path out_;
  std::vector<std::filesystem::path> files_;
};

// A figure in the report: the PNG inline, both files named.
[[nodiscard]] std::string report_image(const std::string& stem, const std::string& alt);
// A Markdown file's body under the report's own heading level: its first "# " title dropped and
// every other heading two levels deeper.
[[nodiscard]] std::string embed_markdown(const std::string& md);

// One paper's experiments in a reproduction, run look by look (one look without --decide).
class PaperRun {
public:
  virtual ~PaperRun() = default;
  // What a look can rerun, in order: names unique across the papers ("buffon/figure5", "los").
  [[nodiscard]] virtual std::vector<std::string> units() const = 0;
  // The unit a claim of this paper reads (default: the paper's one unit).
  [[nodiscard]] virtual std::string unit_of(const ClaimSpec& /*spec*/) const {
    return units().front();
  }
  // Runs `unit` at `factor` times the scale's counts, `trials` (a collective under MPI: every
  // rank calls it; the results are rank 0's).
  virtual void run(const std::string& unit, const Trials& trials, int factor,
                   const algorithms::Runner& runner) = 0;
  // Under --decide, before a look reruns `unit` (rank 0 only): the parts still undecided of the
  // claims that read it. A paper may then run only what they read (paper 000: the arenas whose
  // trials are their samples); run() stays a collective, so it must make every rank agree on what
  // it runs (Runner::any). Returns the next run's work as a share of the unit's last run's
  // (the time budget's prediction); the default runs the whole unit again: 1.
  virtual double narrow(const std::string& /*unit*/, const std::vector<Part>& /*undecided*/) {
    return 1.0;
  }
  // Whether `unit`'s last run extended everything these parts read, so that they are at that
  // look's count (rank 0): a claim that stopped asking is evaluated again only then. Default: a
  // unit always runs whole, so true.
  [[nodiscard]] virtual bool fresh(const std::string& /*unit*/,
                                   const std::vector<Part>& /*parts*/) const {
    return true;
  }
  // What narrow() kept of `unit` for its next run, for the progress line ("3 of 17 arenas"), or
  // "" for all of it (rank 0).
  [[nodiscard]] virtual std::string narrowed_text(const std::string& /*unit*/) const { return {}; }
  // Its results, for its claims (rank 0).
  virtual void inputs(ClaimInputs& in) const = 0;
  // The counts a unit ran at `factor`, in words (a claim's "trials" under --decide).
  [[nodiscard]] virtual std::string trials_text(const Trials& trials, int factor) const = 0;
  // The counts of its last runs, for the report's opening line ("20 trials per arena for paper
  // 000 (the paper: 100)") and claims.json's "trials".
  [[nodiscard]] virtual std::string counts_text() const = 0;
  virtual void counts_json(std::vector<std::pair<std::string, std::int64_t>>& counts) const = 0;
  // Writes its files and its report section, and adds its trace hashes (rank 0). `options` are
  // those that reproduce the report (a --decide run's budget in trials).
  virtual void write(ReportFiles& files, const ReproduceOptions& options, std::ostream& section,
                     std::vector<ExperimentRecord>& records) const = 0;
};

struct PaperEntry {
  std::string id;     // "000"
  std::string family; // its --only name: "buffon"
  const std::vector<ClaimSpec>& (*claims)() = nullptr;
  std::function<std::unique_ptr<PaperRun>(const ReproduceOptions&)> make;
};

// Every registered paper, in id order.
[[nodiscard]] const std::vector<PaperEntry>& papers();

} // namespace antkit::experiments
