#pragma once
// Each subcommand lives in its own file and registers itself at static-initialisation time:
//
//   namespace { const antkit::cli::Registration reg{"arena", &register_arena}; }
//
// main() adds the registered subcommands in name order, so `antkit --help` is stable and no file
// but the subcommand's own changes when a subcommand is added.
#include <CLI/CLI.hpp>
#include <functional>
#include <map>
#include <string>

namespace antkit::cli {

using Registrar = void (*)(CLI::App& app);

// The registered subcommands, by name.
std::map<std::string, Registrar>& registry();

struct Registration {
  Registration(const std::string& name, Registrar registrar) { registry()[name] = registrar; }
};

} // namespace antkit::cli
