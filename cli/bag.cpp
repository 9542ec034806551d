// `antkit bag info BAG`: a ROS 2 bag's topics, types, message counts and time range (issue 42).
//   antkit bag info BAG [--format table|json]
// BAG is an .mcap file, a .db3 file or a rosbag2 folder with a metadata.yaml (io/bag.hpp).
// JSON (commands/bags.hpp, bag_info_json): "bag", "storage" ("mcap" or "sqlite3"), "files",
// "messages", "start_ns", "end_ns" (bag time, ns since the epoch; null without messages),
// "duration_s", "topics": [{"topic", "type", "encoding", "messages", "start_ns", "end_ns"}].
// Exit 2 for a bag that cannot be read, with its location (FILE: byte N in an MCAP file).
#include "commands.hpp"
#include "output.hpp"

#include <antkit/commands/bags.hpp>
#include <iostream>
#include <memory>

namespace {

using antkit::cli::Format;

struct BagInfoCommand {
  std::string bag;
  Format format = Format::Table;
};

void register_bag(CLI::App& app) {
  auto* sub = app.add_subcommand("bag", "Read ROS 2 bags (rosbag2: .mcap, .db3, bag folders)");
  sub->require_subcommand(1);
  auto c = std::make_shared<BagInfoCommand>();
  auto* info = sub->add_subcommand(
      "info", "A bag's topics, their types and message counts, and its time range");
  info->add_option("bag", c->bag, "The bag: an .mcap, a .db3 or a folder with metadata.yaml")
      ->required();
  antkit::cli::add_format_option(*info, c->format);
  info->callback([c] {
    const auto j = antkit::commands::bag_info_json(antkit::io::bag::bag_info(c->bag));
    antkit::cli::emit(j, c->format, std::cout);
  });
}

const antkit::cli::Registration bag_registration{"bag", &register_bag};

} // namespace
