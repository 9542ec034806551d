// `antkit export mcap`: a hardware log as an MCAP file for Foxglove (issue 42).
//   antkit export mcap LOG --out FILE.mcap [--threads N] [--format table|json]
// The channels and their schemas are devices/mcap_export.hpp's. Prints {"log", "out", "bytes",
// "messages", "channels": {topic: messages}}. Exit status 0, or 2 for a log that cannot be read or
// is malformed (its line and column) and an --out that cannot be written; the file is written whole
// or not at all.
#include "commands.hpp"
#include "output.hpp"

#include <antkit/commands/options.hpp>
#include <antkit/devices/mcap_export.hpp>
#include <antkit/kernel/input_error.hpp>
#include <iostream>
#include <memory>

namespace {

using antkit::cli::Format;

struct ExportMcapCommand {
  std::string log, out;
  std::int64_t threads = 0; // 0: one per hardware thread
  Format format = Format::Table;
};

void run(const ExportMcapCommand& c) {
  if (c.threads < 0 || c.threads > 256)
    throw antkit::kernel::InputError("--threads", "the number of threads must be in [0, 256]");
  auto options = antkit::commands::mcap_options();
  options.threads = static_cast<unsigned>(c.threads);
  const auto s = antkit::devices::export_mcap(c.log, c.out, options);
  nlohmann::json channels = nlohmann::json::object();
  for (const auto& [topic, n] : s.channels) channels[topic] = n;
  const nlohmann::json j{{"log", c.log},
                         {"out", c.out},
                         {"bytes", s.bytes},
                         {"messages", s.messages},
                         {"channels", channels}};
  antkit::cli::emit(j, c.format, std::cout);
}

void register_export(CLI::App& app) {
  auto* sub = app.add_subcommand("export", "Convert a recording into another tool's format");
  sub->require_subcommand(1);
  auto c = std::make_shared<ExportMcapCommand>();
  auto* mcap = sub->add_subcommand(
      "mcap", "A hardware log as MCAP (Foxglove's schemas: pose, trail, arena, log; antkit's "
              "steps and exchanged bytes), to open in Foxglove");
  mcap->add_option("log", c->log, "The log (JSON Lines, from antkit record)")->required();
  mcap->add_option("--out", c->out, "The MCAP file to write")->required();
  mcap->add_option("--threads", c->threads,
                   "Threads that format the messages (default 0: one per hardware thread; the "
                   "file's bytes do not depend on it)");
  antkit::cli::add_format_option(*mcap, c->format);
  mcap->callback([c] { run(*c); });
}

const antkit::cli::Registration export_registration{"export", &register_export};

} // namespace
