// `antkit buffon`: Buffon's-needle blind area measurement (issue 4, paper 000).
//
//   antkit buffon --arena SPEC|FILE.wkt [--trials N] [--steps N] [--width W] [--seed S]
//                 [--threads T] [--noise X] [--precision P [--rule online|markers|fixed]
//                 [--max-steps N] [--max-steps2 N]] [--format table|json] [--svg FILE]
//                 [--mcap FILE.mcap]
//
// JSON: {"arena": {"spec", "area"}, "trials": [{"trial", "bc", "nbc", "length1", "length2",
//        "crossings_exact", "area_closed_form", "area_closed_form_ci", "blocked", "hash"}],
//        "summary": {"nbc_median", "nbc_q1", "nbc_q3", "area_closed_form_median"}, "hash"}.
// The top-level hash chains the trials' hashes in trial order. area_closed_form is null when a
// trial saw no crossing; the median is over the trials that have one (null if none). --svg draws
// trial 0's two trails over the arena (visit 1 blue, visit 2 red), like the paper's Figure 4.
// Output bytes do not depend on --threads. --mcap writes trial 0's two visits for Foxglove, one
// after the other at 100 ms a step (commands/buffon_mcap.hpp: the arena, each visit's pose and
// trail, visit 2's crossings of visit 1's trail and the result on /log); refused under --rule
// markers (one walk, no two visits) and for visits of more than 2^22 positions together.
//
// --precision P stops the run as soon as the closed form's 95 % interval, from the two-way
// batch-means variance of the exact crossing count (stopping.hpp), lies within a relative P of
// the estimate, checked every 10 000 steps. --rule says how the trail is laid (issue 17):
//  * markers (the default): one walk lays two markers in alternate 1000-step pieces and stops when
//    the pair's crossings meet P (two_markers.hpp; no pheromone detector, so bc and nbc are 0);
//    length1/length2 are the two markers' trails, capped together by --max-steps (default
//    20 000 000 steps, far more than P >= 0.05 needs).
//  * online: visit 1 decides its own length from its self-crossings (stopping.hpp,
//    FirstVisitMonitor) and stops when a visit 2 of its length would meet P; visit 2 then runs
//    until P is met. --max-steps N is the budget of both visits together (visit 1 at most N / 2,
//    visit 2 what is left; default 20 000 000). --steps and --max-steps2 are not used.
//  * fixed (issue 8, item 5): visit 1 runs --steps, visit 2 until P is met or --max-steps2
//    (default --steps).
// markers is the default because on 60 random polygons with holes it reached P = 0.1 with 0.76
// of the online rule's median total trail, both meeting the accuracy targets
// (tests/convergence/test_first_visit_stats.cpp).
//
// With --precision each trial also has "reached_precision" (false: the run ran out of steps),
// "precision_ci" (the rule's interval), "variance_visit1", "variance_visit2" (the variance's two
// shares: for --rule fixed, when visit 1's dominates only a longer visit 1 helps),
// "wall_encounters", "area_corrected" and "area_corrected_ci" (the erosion-corrected estimate and
// interval, estimate.hpp); the summary has "precision", "reached_precision" (how many trials
// reached it), "length2_median" and "area_corrected_median". With markers or online a trial also
// has "steps1", "steps2", "length_total", "precision_reached" (the interval's upper side over the
// estimate, minus 1: what a trial that ran out of steps did reach) and "stopped" ("precision",
// "visit 1 cap", "visit 2 cap" or "budget"), and with online "first_visit_reached",
// "self_crossings" and "area_pilot" (length1^2 / (pi S)); the summary has "rule",
// "length1_median", "length_total_median", with online "first_visit_reached", and when trials ran
// out of steps a "budget_note", also written to stderr. Without --precision the output is
// unchanged. The JSON is commands::buffon_json's (commands/src/buffon.cpp).
#include "buffon_options.hpp"
#include "commands.hpp"
#include "output.hpp"

#include <antkit/buffon/area_measurement.hpp>
#include <antkit/commands/buffon_mcap.hpp>
#include <antkit/commands/json.hpp>
#include <antkit/experiments/buffon_figures.hpp>
#include <antkit/geometry/fixed_convert.hpp>
#include <antkit/kernel/input_error.hpp>
#include <iostream>
#include <memory>
#include <string>

namespace {

using antkit::cli::Format;
using antkit::kernel::InputError;
namespace buffon = antkit::buffon;
namespace geometry = antkit::geometry;

struct BuffonCommand {
  std::string arena;
  std::int64_t trials = 1;
  std::int64_t steps = buffon::kDefaultSteps;
  std::int64_t max_steps2 = 0; // --max-steps2: visit 2's cap under --precision (0: --steps)
  double width = 0.1;
  double noise = 0.0;
  std::uint64_t seed = 1;
  std::int64_t threads = 1;
  std::string svg, png, mcap;
  std::string precision;        // as typed; read exactly by parse_precision
  bool precision_given = false; // without --precision visit 2 runs all --steps
  std::string rule = "markers"; // --rule markers|online|fixed (issue 17: markers need less trail)
  bool rule_given = false;
  std::int64_t max_steps = 0; // --max-steps: the budget of both visits (online, markers)
  Format format = Format::Table;
};

void run(const BuffonCommand& c) {
  antkit::cli::check_buffon_run_size(c.trials, c.steps, c.threads);
  if (c.max_steps2 != 0 && !c.precision_given)
    throw InputError("--max-steps2", "--max-steps2 needs --precision");
  if (c.max_steps2 < 0 || c.max_steps2 > 100000000)
    throw InputError("--max-steps2", "visit 2's step cap must be in [1, 100000000]");
  const buffon::PrecisionRule rule = buffon::parse_rule(c.rule);
  if (c.rule_given && !c.precision_given) throw InputError("--rule", "--rule needs --precision");
  if (c.max_steps != 0 && !c.precision_given)
    throw InputError("--max-steps", "--max-steps (both visits' budget) needs --precision");
  const bool online1 = c.precision_given && rule == buffon::PrecisionRule::online;
  const bool markers = c.precision_given && rule == buffon::PrecisionRule::markers;
  if (c.max_steps != 0 && !online1 && !markers)
    throw InputError("--max-steps", "--max-steps (both visits' budget) needs --rule online or "
                                    "markers");
  if (c.max_steps2 != 0 && (markers || online1))
    throw InputError("--max-steps2", "--max-steps2 caps visit 2 of --rule fixed; --rule markers "
                                     "(the default) and online take --max-steps, the budget of "
                                     "both visits");
  if (c.max_steps < 0 || c.max_steps == 1 || c.max_steps > 100000000)
    throw InputError("--max-steps", "the budget for both visits must be in [2, 100000000]");
  antkit::cli::check_buffon_body(c.width, c.noise);

  const geometry::Arena arena = antkit::cli::read_buffon_arena(c.arena);
  const buffon::World world = antkit::cli::buffon_world(arena, c.noise);
  buffon::AreaMeasurementParams params;
  params.trials = static_cast<std::uint64_t>(c.trials);
  params.threads = static_cast<unsigned>(c.threads);
  params.seed = c.seed;
  params.steps = c.steps;
  params.width = geometry::fixed_from_double<antkit::kernel::Fx>(c.width, "--width");
  if (c.precision_given) {
    params.precision_millionths = buffon::parse_precision(c.precision);
    params.rule = rule;
    params.visit2_steps = c.max_steps2;
    params.total_steps = c.max_steps;
  }
  params.keep_first_trails = !c.svg.empty() || !c.png.empty() || !c.mcap.empty();
  if (!c.mcap.empty()) antkit::commands::check_buffon_mcap(params);
  const buffon::AreaMeasurement m = buffon::measure_area(world, params);
  // The MCAP file before anything else: its size check (the online rule's lengths) may refuse after
  // the run, before any file is written or anything printed.
  if (!c.mcap.empty())
    (void)antkit::commands::write_buffon_mcap(world, m, params, c.arena, arena.area(), c.mcap);

  nlohmann::json result = antkit::commands::buffon_json(m, params, c.arena, arena.area());
  if (buffon::budgeted(params) && m.summary.out_of_steps > 0) {
    // Said on stderr too, where a table reader looks for trouble.
    const std::string note = std::to_string(m.summary.out_of_steps) + " of " +
                             std::to_string(c.trials) +
                             " trials ran out of steps before reaching P = " + c.precision +
                             "; their precision_reached says what they reached (raise --max-steps)";
    result["summary"]["budget_note"] = note;
    std::cerr << "antkit: note: " << note << '\n';
  }
  if (!c.svg.empty() || !c.png.empty())
    antkit::experiments::save_trial_trails_figure(c.arena, arena, m.trials[0].run, c.steps, c.svg,
                                                  c.png);
  antkit::cli::emit(result, c.format, std::cout);
}

void register_buffon(CLI::App& app) {
  auto options = std::make_shared<BuffonCommand>();
  auto* sub = app.add_subcommand(
      "buffon", "Buffon's-needle blind area measurement: two visits, BC, nBC, closed-form area");
  sub->add_option("--arena", options->arena, "A named arena spec (circle:d=100, ...) or FILE.wkt")
      ->required();
  sub->add_option("--trials", options->trials, "Number of trials (default 1)");
  sub->add_option("--steps", options->steps, "Steps per visit (default 50000)");
  sub->add_option("--width", options->width, "Pheromone trail width in robot diameters (0.1)");
  sub->add_option("--noise", options->noise, "IR sensor noise amplitude in [0, 1] (default 0)");
  sub->add_option("--seed", options->seed, "Seed of the keyed streams (default 1)");
  sub->add_option("--threads", options->threads, "Worker threads (default 1)");
  auto* precision = sub->add_option(
      "--precision", options->precision,
      "Stop as soon as the 95 % interval of the closed-form area (exact crossings, two-way "
      "batch-means variance) is within this relative precision P in (0, 1), at most six "
      "decimals; checked every 10000 steps; how the trail is laid is --rule's");
  sub->add_option("--max-steps2", options->max_steps2,
                  "With --rule fixed: visit 2's step cap (default: --steps)");
  auto* rule = sub->add_option(
      "--rule", options->rule,
      "With --precision: 'markers' (one walk lays two alternating markers and stops when their "
      "crossings meet P; the default: the least trail), 'online' (visit 1 stops when its "
      "self-crossings say a visit 2 of its length meets P) or 'fixed' (visit 1 runs --steps)");
  sub->add_option("--max-steps", options->max_steps,
                  "With --rule online or markers: the step budget of both visits together "
                  "(default 20000000)");
  sub->add_option("--svg", options->svg,
                  "Draw trial 0's trails to this SVG file (title, legend, caption)");
  sub->add_option("--png", options->png, "The same picture as PNG");
  sub->add_option("--mcap", options->mcap,
                  "Write trial 0's two visits as MCAP for Foxglove (the arena, each visit's pose "
                  "and trail at 100 ms a step, the crossings and the result on /log)");
  antkit::cli::add_format_option(*sub, options->format);
  sub->callback([options, precision, rule] {
    options->precision_given = precision->count() > 0;
    options->rule_given = rule->count() > 0;
    run(*options);
  });
}

const antkit::cli::Registration buffon_registration{"buffon", &register_buffon};

} // namespace
