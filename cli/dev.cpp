// `antkit dev`: the plumbing the project's own scripts and tests call, kept out of the user's
// commands. Its subcommands register with DevRegistration (commands.hpp), one file each
// (dev_<name>.cpp): today the Cortex-M image's input writers that scripts/run-on-mcu.sh and
// tests/mcu/ run (stc-mcu-input, buffon-mcu-input, rs-mcu-input, wanderer-mcu-input).
//
//   antkit dev NAME [options]
//
// `antkit --help` lists `dev` once, under its own "Plumbing" heading after the user's commands, so
// that whoever reads the help learns where the scripts' commands went without taking them for
// commands of their own; `antkit dev --help` lists them. The exit status and messages are those of
// every command (main.cpp).
#include "commands.hpp"

namespace {

void register_dev(CLI::App& app) {
  auto* dev = app.add_subcommand(
      "dev", "Plumbing for the project's own scripts and tests (antkit dev --help lists it)");
  dev->group("Plumbing");
  dev->footer("Not commands for users: each writes or checks what a script of this project "
              "(scripts/run-on-mcu.sh, tests/mcu/) needs; their options follow the command they "
              "serve (antkit stc, buffon, cover) and are refused as that command refuses them.");
  dev->require_subcommand(1);
  for (const auto& [name, command] : antkit::cli::registry())
    if (command.group == antkit::cli::Group::dev) command.registrar(*dev);
}

const antkit::cli::Registration dev_registration{"dev", &register_dev};

} // namespace
