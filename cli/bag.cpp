// `antkit bag info BAG`: a ROS 2 bag's topics, types, message counts and time range (issue 42).
//   antkit bag info BAG [--format table|json]
// BAG is an .mcap file, a .db3 file or a rosbag2 folder with a metadata.yaml (io/bag.hpp).
// JSON (commands/bags.hpp, bag_info_json): "bag", "storage" ("mcap" or "sqlite3"), "files",
// "messages", "start_ns", "end_ns" (bag time, ns since the epoch; null without messages),
// "duration_s", "topics": [{"topic", "type", "encoding", "messages", "start_ns", "end_ns"}].
//   antkit bag export BAG --map M --topic T [--topic T2 ...] --out F.mcap [--check stc|cover]
//                     [--sensor R] [--stamp bag|header] [--child-frame F] [--format table|json]
// the bag's poses back out to MCAP with the map and the check's result (commands/bags.hpp,
// export_bag_mcap, lists the channels); prints bag_mcap_json; exit 1 when the check fails (the
// file is written: the failure is what it shows).
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

struct BagExportCommand {
  antkit::commands::BagMcapRequest r;
  std::string stamp = "bag";
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

  auto e = std::make_shared<BagExportCommand>();
  auto* exp = sub->add_subcommand(
      "export", "A bag's pose topics as MCAP for Foxglove, with the map and a check's result");
  exp->add_option("bag", e->r.bag, "The bag: an .mcap, a .db3 or a folder with metadata.yaml")
      ->required();
  exp->add_option("--map", e->r.map_file, "The map (ROS .yaml, MovingAI .map, ASCII .txt)")
      ->required();
  exp->add_option("--topic", e->r.topics, "A robot's pose topic (repeat for more)")->required();
  exp->add_option("--out", e->r.out, "The MCAP file to write")->required();
  exp->add_option("--check", e->r.check,
                  "stc (one topic) or cover (with --sensor): its result on "
                  "/log, an ERROR at the first violation's time");
  exp->add_option("--sensor", e->r.sensor, "With --check cover: the sensor distance in cells");
  exp->add_option("--stamp", e->stamp, "The poses' time, bag or header");
  exp->add_option("--child-frame", e->r.child_frame,
                  "On a TFMessage topic: the child frame (default base_link)");
  antkit::cli::add_format_option(*exp, e->format);
  exp->callback([e] {
    e->r.stamp = antkit::commands::bag_stamp(e->stamp, "--stamp");
    const auto s = antkit::commands::export_bag_mcap(e->r);
    antkit::cli::emit(antkit::commands::bag_mcap_json(e->r, s), e->format, std::cout);
    if (!s.check_ok) throw antkit::cli::CheckFailed(e->r.bag + ": " + s.check_text);
  });
}

const antkit::cli::Registration bag_registration{"bag", &register_bag};

} // namespace
