// `antkit campaign`: property campaigns on antkit's own kernels (issue 18). The engine is
// antkit_campaign (testing/campaign/); this file parses options, calls it, prints.
//
//   antkit campaign stc|los|uniform|buffon --cases N --out DIR [--seed S] [--first I] [--max-size
//   WxH]
//                   [--variants a,b,...] [--time T] [--threads T] [--plant max-width=N]
//                   [--format table|json]
//   mpirun -n K antkit campaign ...       (the cases split across K ranks, the same output files)
//
// DIR/summary.json and a MovingAI map per failing case (shrunk, with the command that reproduces
// it) hold only what the options determine; timings (cases per second) go to standard output and,
// on a terminal, a progress bar to standard error. Exit status: 0 no case broke a rule, 1 some did,
// 2 bad input.
#if ANTKIT_HAVE_CAMPAIGN
#include "commands.hpp"
#include "output.hpp"
#include "ranks.hpp"

#include <antkit/algorithms/options.hpp>
#include <antkit/campaign/campaign.hpp>
#include <antkit/kernel/input_error.hpp>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <unistd.h>

namespace {

using antkit::cli::Format;
namespace campaign = antkit::campaign;
using antkit::kernel::InputError;

struct CampaignCommand {
  std::string family;
  std::int64_t cases = 0;
  std::uint64_t seed = 1;
  std::uint64_t first = 0;
  std::string max_size = "32x32";
  std::string variants;
  double time = 0;
  std::int64_t threads = 1;
  std::string plant;
  std::string out;
  Format format = Format::Table;
};

campaign::Options options_of(const CampaignCommand& c) {
  campaign::Options o;
  const auto family = campaign::parse_family(c.family);
  if (!family)
    throw InputError("FAMILY",
                     "'" + c.family + "' is not a campaign; expected stc, los or uniform");
  o.family = *family;
  if (c.cases < 1) throw InputError("--cases", "expected at least one case");
  o.cases = static_cast<std::uint64_t>(c.cases);
  o.seed = c.seed;
  o.first = c.first;
  const auto [w, h] = antkit::algorithms::parse_pair("--max-size", c.max_size, 'x', "WxH");
  if (w < 1 || h < 1 || w > 1024 || h > 1024)
    throw InputError("--max-size", "expected a size from 1x1 to 1024x1024, not " + c.max_size);
  o.max_width = static_cast<std::int32_t>(w);
  o.max_height = static_cast<std::int32_t>(h);
  for (std::size_t from = 0; !c.variants.empty() && from <= c.variants.size();) {
    const auto comma = std::min(c.variants.find(',', from), c.variants.size());
    o.variants.push_back(c.variants.substr(from, comma - from));
    from = comma + 1;
  }
  o.time_limit_s = c.time;
  if (c.threads < 1 || c.threads > 256)
    throw InputError("--threads", "expected 1 to 256 threads, not " + std::to_string(c.threads));
  if (!c.plant.empty() && o.family == campaign::Family::Buffon)
    throw InputError("--plant", "a planted rule is about grid maps: stc, los or uniform");
  if (!c.plant.empty()) { // a planted failure: maps wider than N break it
    constexpr std::string_view kKey = "max-width=";
    if (c.plant.rfind(kKey, 0) != 0)
      throw InputError("--plant", "'" + c.plant + "' is not a rule to plant; expected max-width=N");
    const auto n =
        antkit::algorithms::parse_integer("--plant", c.plant.substr(kKey.size()), "a width");
    if (n < 0 || n > 1024) throw InputError("--plant", "expected a width in [0, 1024]");
    o.extra_rule = [n](const antkit::kernel::OccupancyGrid& m) {
      return m.width() > n ? "wider than " + std::to_string(n) + " cells (planted)" : "";
    };
    o.extra_rule_name = c.plant;
  }
  campaign::validate(o);
  return o;
}

void run(const CampaignCommand& c) {
  const campaign::Options o = options_of(c);
  const bool tty = ::isatty(STDERR_FILENO) == 1;
  const auto started = std::chrono::steady_clock::now();
  auto seconds = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  };
  const antkit::algorithms::Progress progress = [&](std::string_view, std::uint64_t done,
                                                    std::uint64_t total) {
    if (!tty) return;
    const double s = seconds(), rate = static_cast<double>(done) / std::max(s, 1e-9);
    const int filled =
        static_cast<int>(30.0 * static_cast<double>(done) / static_cast<double>(total));
    std::cerr << "\rcampaign " << c.family << " ["
              << std::string(static_cast<std::size_t>(filled), '#')
              << std::string(static_cast<std::size_t>(30 - filled), '.') << "] " << done << "/"
              << total << ", " << std::fixed << std::setprecision(0) << rate << " cases/s, about "
              << static_cast<double>(total - done) / std::max(rate, 1e-9) << " s left   "
              << std::defaultfloat << std::setprecision(6) << std::flush;
  };
  const auto threads = static_cast<unsigned>(c.threads);
  campaign::Result result;
  // Under mpirun every rank runs its share and rank 0 gathers, writes and prints.
  const int ranks = antkit::cli::run_on_ranks(
      c.out, threads, progress,
      [&](const antkit::algorithms::Runner& runner) { result = campaign::run(o, runner); });
  if (ranks == 0) return; // another rank than 0: rank 0 writes and prints
  const double elapsed = seconds();
  if (tty) std::cerr << '\n';
  campaign::write_outputs(o, result, c.out);
  nlohmann::json j;
  j["family"] = c.family;
  j["cases_run"] = result.cases_run;
  j["stopped_by_time"] = result.stopped_by_time;
  j["failures"] = result.failures.size();
  j["moves_checked"] = result.moves;
  j["vacuous_cases"] = result.vacuous;
  j["seconds"] = elapsed;
  j["cases_per_second"] = static_cast<double>(result.cases_run) / std::max(elapsed, 1e-9);
  j["moves_per_second"] = static_cast<double>(result.moves) / std::max(elapsed, 1e-9);
  j["threads"] = threads;
  j["ranks"] = ranks;
  j["summary"] = (std::filesystem::path(c.out) / "summary.json").string();
  antkit::cli::emit(j, c.format, std::cout);
  if (result.stopped_by_time)
    std::cerr << "antkit campaign: the time limit stopped the campaign after " << result.cases_run
              << " of " << o.cases << " cases\n";
  if (!result.failures.empty())
    throw antkit::cli::CheckFailed(std::to_string(result.failures.size()) + " of " +
                                   std::to_string(result.cases_run) +
                                   " cases broke a rule; the shrunk maps and their commands are "
                                   "in " +
                                   j["summary"].get<std::string>());
}

void register_campaign(CLI::App& app) {
  auto c = std::make_shared<CampaignCommand>();
  auto* sub = app.add_subcommand(
      "campaign", "Run a property campaign: generated maps, every variant of a family, every "
                  "invariant checked, failing cases shrunk to minimal maps");
  sub->add_option("family", c->family, "stc, los, uniform or buffon")->required();
  sub->add_option("--cases", c->cases, "Number of cases")->required();
  sub->add_option("--out", c->out, "Output directory (summary.json, shrunk failing maps)")
      ->required();
  sub->add_option("--seed", c->seed, "Seed of the keyed streams that draw the cases (default 1)");
  sub->add_option("--first", c->first, "Index of the first case (default 0)");
  sub->add_option("--max-size", c->max_size,
                  "Largest map, WxH (stc: cells of 2 x 2 sub-cells; default 32x32)");
  sub->add_option("--variants", c->variants, "Comma-separated variants (default: all)");
  sub->add_option("--time", c->time, "Stop at a case boundary after this many seconds");
  sub->add_option("--threads", c->threads, "Threads that check cases (default 1; per MPI rank)");
  sub->add_option("--plant", c->plant,
                  "Plant a failing rule, max-width=N (maps wider than N break it), to see the "
                  "shrinking and the failure outputs at work");
  antkit::cli::add_format_option(*sub, c->format);
  sub->callback([c] { run(*c); });
}

// campaign::validate()'s words for its inputs, as this command's options.
const antkit::cli::Registration campaign_registration{"campaign",
                                                      &register_campaign,
                                                      {{"cases", "--cases"},
                                                       {"first case", "--first"},
                                                       {"largest map", "--max-size"},
                                                       {"time limit", "--time"},
                                                       {"variants", "--variants"}}};

} // namespace
#endif
