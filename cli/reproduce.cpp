// `antkit reproduce [--quick | --full] [--decide [--budget TRIALS|DURATION]]
//                   [--only buffon,los,stc,uniform] [--threads T] [--seed S] [--maps DIR] --out DIR
//                   [--format table|json]`: every paper's experiments in one run, with the claims
// table (issue 15); --decide adds trials until each claim is decided or the budget is spent
// (issue 44): TRIALS is paper 000's trials per arena at the last look, DURATION a number with s, m
// or h (30m): the looks go on while the next one's predicted time fits, and the report states the
// trials reached. The experiments, the report and the verdicts are documented in
// experiments/include/antkit/experiments/reproduce.hpp.
//
//   mpirun -n K antkit reproduce --full ...   splits the trials across K MPI ranks; rank 0
//                                             gathers them and writes the same files
//
// Prints the claims table (or, with --format json, the verdicts and the files) on stdout and
// progress on stderr: a live bar with the time left on a terminal, a line per quarter of each
// stage otherwise. Exit status 0 whatever the verdicts (a claim that does not hold is a finding,
// not an error), 2 for bad options.
#include "commands.hpp"
#include "output.hpp"
#include "ranks.hpp"

#include <antkit/experiments/plot.hpp>
#include <antkit/experiments/reproduce.hpp>
#include <antkit/kernel/input_error.hpp>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <unistd.h>

namespace {

namespace ex = antkit::experiments;
using antkit::kernel::InputError;

struct ReproduceCommand {
  bool quick = false, full = false, decide = false;
  std::string budget;
  std::vector<std::string> unit_budget; // UNIT=TRIALS
  std::string only;
  std::int64_t threads = 2;
  std::uint64_t seed = 1;
  std::string maps = "data/maps";
  std::string out;
  antkit::cli::Format format = antkit::cli::Format::Table;
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> parts;
  std::size_t from = 0;
  while (from <= s.size()) {
    const auto comma = std::min(s.find(',', from), s.size());
    parts.push_back(s.substr(from, comma - from));
    from = comma + 1;
  }
  return parts;
}

// --budget: a count of trials, or a duration (a number and s, m or h).
void parse_budget(const std::string& text, ex::ReproduceOptions& o) {
  if (text.empty()) return;
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  const std::string unit = text.substr(used);
  const bool digits = text.find_first_not_of("0123456789") == std::string::npos;
  if (used == 0 || !(value > 0) || (unit.empty() && !digits))
    throw InputError("--budget", "expected trials per arena (800) or a duration (600s, 30m, 2h), "
                                 "not '" +
                                     text + "'");
  if (unit.empty()) {
    if (text.size() > 7) throw InputError("--budget", "at most 100000 trials per arena");
    o.budget_trials = std::stoll(text);
    return;
  }
  const double scale = unit == "s" ? 1 : unit == "m" ? 60 : unit == "h" ? 3600 : 0;
  if (scale == 0) throw InputError("--budget", "the unit of '" + text + "' must be s, m or h");
  o.budget_seconds = value * scale;
}

void run(const ReproduceCommand& c) {
  if (c.quick && c.full) throw InputError("--full", "give --quick or --full, not both");
  if (c.threads < 1 || c.threads > 256)
    throw InputError("--threads", "expected 1 to 256 threads, not " + std::to_string(c.threads));
  ex::ReproduceOptions o;
  // --decide starts from the papers' counts unless --quick is given.
  o.scale = c.full || (c.decide && !c.quick) ? ex::Scale::Full : ex::Scale::Quick;
  o.decide = c.decide;
  if (!c.budget.empty() && !c.decide) throw InputError("--budget", "a budget is for --decide");
  parse_budget(c.budget, o);
  for (const auto& text : c.unit_budget) {
    const auto eq = text.find('=');
    const std::string n = eq == std::string::npos ? "" : text.substr(eq + 1);
    if (eq == 0 || n.empty() || n.size() > 7 || n.find_first_not_of("0123456789") != n.npos)
      throw InputError("--unit-budget",
                       "expected UNIT=TRIALS (buffon/figure14=400), not '" + text + "'");
    o.unit_budget[text.substr(0, eq)] = std::stoll(n);
  }
  if (!c.only.empty()) o.only = split(c.only);
  o.seed = c.seed;
  o.out = c.out;
  o.maps_dir = c.maps;
  ex::validate(o);

  const auto start = std::chrono::steady_clock::now();
  const auto seconds = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  ex::ReproduceReport report;
  const int ranks = antkit::cli::run_on_ranks(
      c.out, static_cast<unsigned>(c.threads), antkit::cli::stage_progress("reproduce"),
      [&](const antkit::algorithms::Runner& runner) { report = ex::reproduce(o, runner); });
  if (ranks == 0) return; // another rank than 0: rank 0 prints
  ex::release_drawing_caches();
  if (c.decide)
    std::cerr << "reproduce: " << report.looks << " look(s); the last at " << report.budget_trials
              << " trials per arena (rerun with " << report.rerun << " for the same bytes)\n";
  std::cerr << "reproduce: done in " << std::fixed << std::setprecision(1) << seconds() << " s ("
            << c.threads << " thread(s) x " << ranks << " rank(s)); report in "
            << (std::filesystem::path(c.out) / "README.md").string() << '\n'
            << std::defaultfloat << std::setprecision(6);
  if (c.format == antkit::cli::Format::Json) {
    nlohmann::json j;
    nlohmann::json claims = nlohmann::json::array();
    for (const auto& claim : report.claims)
      claims.push_back({{"id", claim.id},
                        {"verdict", ex::verdict_text(claim.verdict)},
                        {"measured", claim.measured}});
    j["claims"] = std::move(claims);
    nlohmann::json files = nlohmann::json::array();
    for (const auto& f : report.files) files.push_back((std::filesystem::path(c.out) / f).string());
    j["files"] = std::move(files);
    j["seconds"] = seconds();
    j["ranks"] = ranks;
    antkit::cli::emit(j, c.format, std::cout);
  } else {
    std::cout << ex::claims_markdown(report.claims);
  }
}

void register_reproduce(CLI::App& app) {
  auto c = std::make_shared<ReproduceCommand>();
  auto* sub = app.add_subcommand(
      "reproduce", "Every paper's experiments in one run: tables, figures (SVG and PNG) and a "
                   "claims table with verdicts, in DIR/README.md and DIR/claims.json");
  sub->add_flag("--quick", c->quick, "Fewer trials (the default; stated in the report)");
  sub->add_flag("--full", c->full, "The papers' trial counts");
  sub->add_flag("--decide", c->decide,
                "Add trials, look after look, until every claim is decided or the budget is "
                "spent (from the papers' counts, or --quick's)");
  sub->add_option("--budget", c->budget,
                  "With --decide: paper 000's trials per arena at the last look (default 8 times "
                  "the first look's), or a duration such as 30m");
  sub->add_option("--unit-budget", c->unit_budget,
                  "With --decide, repeatable: UNIT=TRIALS, a unit (buffon/figure14, los, ...) "
                  "runs no look past TRIALS (as --budget); a time budget's report names them");
  sub->add_option("--only", c->only, "Comma-separated: buffon, los, stc, uniform (default: all)");
  sub->add_option("--threads", c->threads, "Threads (default 2; per MPI rank)");
  sub->add_option("--seed", c->seed, "Seed of the keyed streams (default 1)");
  sub->add_option(
      "--maps", c->maps,
      "The real maps for paper 002 (default data/maps, the checkout's copy; when missing, "
      "random maps only)");
  sub->add_option("--out", c->out, "Output directory")->required();
  antkit::cli::add_format_option(*sub, c->format);
  sub->callback([c] { run(*c); });
}

const antkit::cli::Registration reproduce_registration{
    "reproduce", &register_reproduce, {{"output directory", "--out"}, {"families", "--only"}}};

} // namespace
