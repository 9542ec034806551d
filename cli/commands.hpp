#pragma once
// Each subcommand lives in its own file and registers itself at static-initialisation time:
//
//   namespace { const antkit::cli::Registration arena_registration{"arena", &register_arena}; }
//
// The registration is named for its file: cli/ compiles as a unity build (several files in one
// translation unit, cli/CMakeLists.txt), so names in a file's anonymous namespace must not repeat
// another file's.
//
// main() adds the registered subcommands in name order, so `antkit --help` is stable and no file
// but the subcommand's own changes when a subcommand is added. The file is named for the command
// it registers (`explore-tables` in explore_tables.cpp); one command, one file.
//
// Plumbing that only the project's own scripts and tests call (the Cortex-M image's input writers
// for scripts/run-on-mcu.sh) registers under `antkit dev` (dev.cpp), out of the user's list:
//
//   namespace { const antkit::cli::DevRegistration dev_stc_mcu_input_registration{"stc-mcu-input",
//   &register_fn}; }
//
// in dev_stc_mcu_input.cpp. Names are unique across both groups (one registry).
//
// The library names its inputs in its own words (kernel::InputError::where(): "baud rate",
// "largest map"); the command line shows each as the option that carries it. The same word can be
// a different option in two commands (a campaign's "largest map" is --max-size, cover's "map size"
// is --size), so a subcommand whose library calls throw words of their own registers its words
// with it:
//
//   const antkit::cli::Registration campaign_registration{"campaign", &register_campaign,
//                                                         {{"largest map", "--max-size"}, {"time
//                                                         limit", "--time"}}};
//
// main.cpp's shown() looks up where() in the words of the subcommand that ran, then in the words
// every command shows alike (main.cpp), and otherwise shows where() as it is (a file position, a
// spec, an option the command itself named).
#include <CLI/CLI.hpp>
#include <functional>
#include <map>
#include <string>
#include <utility>

namespace antkit::cli {

using Registrar = void (*)(CLI::App& app);

// A library's word for an input -> the option that carries it, e.g. "baud rate" -> "--baud".
using FlagWords = std::map<std::string, std::string, std::less<>>;

// Where a subcommand is added: beside the user's commands, or under `antkit dev`.
enum class Group { user, dev };

struct Command {
  Registrar registrar = nullptr;
  FlagWords flags; // the words of the subcommand named as registered
  Group group = Group::user;
};

// The registered subcommands, by name.
std::map<std::string, Command>& registry();

struct Registration {
  Registration(const std::string& name, Registrar registrar, FlagWords flags = {}) {
    registry()[name] = Command{registrar, std::move(flags), Group::user};
  }
};

// A plumbing subcommand: `antkit dev NAME`, listed by `antkit dev --help` only.
struct DevRegistration {
  DevRegistration(const std::string& name, Registrar registrar, FlagWords flags = {}) {
    registry()[name] = Command{registrar, std::move(flags), Group::dev};
  }
};

} // namespace antkit::cli
