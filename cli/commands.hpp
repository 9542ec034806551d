#pragma once
// Each subcommand lives in its own file and registers itself at static-initialisation time:
//
//   namespace { const antkit::cli::Registration reg{"arena", &register_arena}; }
//
// main() adds the registered subcommands in name order, so `antkit --help` is stable and no file
// but the subcommand's own changes when a subcommand is added.
//
// The library names its inputs in its own words (kernel::InputError::where(): "baud rate",
// "largest map"); the command line shows each as the option that carries it. The same word can be
// a different option in two commands (a campaign's "largest map" is --max-size, cover's "map size"
// is --size), so a subcommand whose library calls throw words of their own registers its words
// with it:
//
//   const antkit::cli::Registration reg{"campaign", &register_campaign,
//                                       {{"largest map", "--max-size"}, {"time limit", "--time"}}};
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

struct Command {
  Registrar registrar = nullptr;
  FlagWords flags; // the words of the subcommand named as registered
};

// The registered subcommands, by name.
std::map<std::string, Command>& registry();

struct Registration {
  Registration(const std::string& name, Registrar registrar, FlagWords flags = {}) {
    registry()[name] = Command{registrar, std::move(flags)};
  }
};

} // namespace antkit::cli
