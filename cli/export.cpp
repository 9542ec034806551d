// `antkit export mcap`: a hardware log as an MCAP file for Foxglove (issue 42).
//   antkit export mcap LOG --out FILE.mcap [--format table|json]
// The channels and their schemas are devices/mcap_export.hpp's. Prints {"log", "out", "bytes",
// "messages", "channels": {topic: messages}}. Exit status 0, or 2 for a log that cannot be read or
// is malformed (its line and column) and an --out that cannot be written; the file is written whole
// or not at all.
#include "commands.hpp"
#include "output.hpp"

#include <antkit/commands/options.hpp>
#include <antkit/devices/mcap_export.hpp>
#include <iostream>
#include <memory>

namespace {

using antkit::cli::Format;

struct ExportMcapCommand {
  std::string log, out;
  Format format = Format::Table;
};

void run(const ExportMcapCommand& c) {
  const auto s = antkit::devices::export_mcap(c.log, c.out, antkit::commands::mcap_options());
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
  antkit::cli::add_format_option(*mcap, c->format);
  mcap->callback([c] { run(*c); });
}

const antkit::cli::Registration export_registration{"export", &register_export};

} // namespace
