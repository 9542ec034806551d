// `antkit replay`: a hardware log through its controller, checked bit for bit (issue 13).
//   antkit replay LOG [--until STEP] [--mcap FILE.mcap] [--format table|json]
// Exit status: 0 identical, 1 at the first divergence (step, field, expected = what the log holds,
// actual = what the replay derived), 2 for a malformed log (line and reason). JSON: {"steps",
// "identical", "first_divergence": null | {"step", "field", "expected", "actual"}, "truncated",
// "complete", "hash", "robot", "controller", "stopped"}. A log without its stop record (the run
// never said how it ended: a power cut, a crash) replays as far as it goes, "complete": false, with
// a warning on stderr; the exit status is then that of the steps it holds. --mcap writes the
// recorded and the replayed run side by side, the first divergence as a foxglove.Log error at its
// step (devices/mcap_export.hpp), whatever the verdict.
#include "commands.hpp"
#include "output.hpp"

#include <antkit/commands/json.hpp>
#include <antkit/commands/options.hpp>
#include <antkit/devices/mcap_export.hpp>
#include <antkit/devices/replay.hpp>
#include <antkit/kernel/input_error.hpp>
#include <iostream>
#include <memory>

namespace {

namespace devices = antkit::devices;
using antkit::cli::Format;

struct ReplayCommand {
  std::string log;
  std::int64_t until = -1;
  std::string mcap;
  Format format = Format::Table;
};

void run(const ReplayCommand& c) {
  if (c.until < -1) throw antkit::kernel::InputError("--until", "expected a step number >= 0");
  const auto r =
      devices::replay(c.log, c.until >= 0 ? std::optional<std::int64_t>(c.until) : std::nullopt);
  if (!c.mcap.empty())
    antkit::devices::export_replay_mcap(c.log, r, c.mcap, antkit::commands::mcap_options());
  const nlohmann::json j = antkit::commands::replay_json(r);
  antkit::cli::emit(j, c.format, std::cout);
  if (r.truncated)
    std::cerr << "antkit: warning: " << c.log
              << ": the last line is cut short (the recording was interrupted while writing); "
                 "every step before it was replayed\n";
  else if (!r.complete && c.until < 0)
    std::cerr << "antkit: warning: " << c.log
              << ": the log has no stop record: the run never said how it stopped (a power cut "
                 "or a crash while recording?); the robot may not have been stopped; every step "
                 "in it was replayed\n";
  if (!r.identical) {
    const auto& d = *r.first_divergence;
    throw antkit::cli::CheckFailed(c.log + ": step " + std::to_string(d.step) + ": " + d.field +
                                   ": the log holds " + d.expected + ", the replay derived " +
                                   d.actual);
  }
}

void register_replay(CLI::App& app) {
  auto c = std::make_shared<ReplayCommand>();
  auto* sub = app.add_subcommand(
      "replay", "Replay a hardware log through the controller named in its header and check "
                "every observation, command and state hash");
  sub->add_option("log", c->log, "The log (JSON Lines, from antkit record)")->required();
  sub->add_option("--until", c->until, "Replay only the steps before this one");
  sub->add_option("--mcap", c->mcap,
                  "Also write the recorded and the replayed run, and the first divergence, as MCAP "
                  "(for Foxglove)");
  antkit::cli::add_format_option(*sub, c->format);
  sub->callback([c] { run(*c); });
}

const antkit::cli::Registration replay_registration{"replay", &register_replay};

} // namespace
