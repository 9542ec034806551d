// antkit: the command-line front of the kit. Exit status: 0 success, 1 a failed check, 2 bad input
// (DESIGN.md, Errors).
#include "commands.hpp"
#include "output.hpp"

#include <antkit/kernel/input_error.hpp>
#include <exception>
#include <iostream>
#include <map>
#include <string>

namespace antkit::cli {
std::map<std::string, Command>& registry() {
  static std::map<std::string, Command> commands;
  return commands;
}
} // namespace antkit::cli

namespace {

// An option given with an empty value ("--start ''") is bad input, not the option left out: every
// option that takes a value, in every subcommand, refuses an empty one (exit 2, naming the option).
void refuse_empty_values(CLI::App& app) {
  const CLI::Validator non_empty(
      [](std::string& value) -> std::string {
        return value.empty() ? "an empty value; give one, or leave the option out" : "";
      },
      "", "non-empty");
  for (CLI::Option* option : app.get_options())
    if (option->get_items_expected_max() > 0) option->check(non_empty);
  for (CLI::App* sub : app.get_subcommands({})) refuse_empty_values(*sub);
}

// The registered subcommand that ran: the top-level one, or under `antkit dev` the plumbing one
// (dev.cpp). Null before parsing.
const antkit::cli::Command* ran(const CLI::App& app) {
  const auto& commands = antkit::cli::registry();
  for (const CLI::App* sub : app.get_subcommands()) {
    for (const CLI::App* inner : sub->get_subcommands()) {
      const auto it = commands.find(inner->get_name());
      if (it != commands.end() && it->second.group == antkit::cli::Group::dev) return &it->second;
    }
    const auto it = commands.find(sub->get_name());
    if (it != commands.end()) return &it->second;
  }
  return nullptr;
}

// The library names its inputs in its own words (InputError::where(): "trail width", "stopping
// rule"); the command line shows each as the option that carries it (commands.hpp): the words the
// subcommand that ran registered, then the words below, which every command shows as the same
// option. Every other where() (a file position, a spec, an option the command itself named) is
// shown as it is.
std::string shown(const antkit::kernel::InputError& e, const CLI::App& app) {
  static const antkit::cli::FlagWords common = {
      {"precision", "--precision"},     {"stopping rule", "--rule"},    {"trail width", "--width"},
      {"step budget", "--max-steps"},   {"steps per visit", "--steps"}, {"trials", "--trials"},
      {"sensor distance", "--sensor"},  {"map size", "--size"},         {"robots", "--robots"},
      {"obstacle density", "--density"}};
  const std::string& where = e.where();
  if (const antkit::cli::Command* command = ran(app)) {
    const auto it = command->flags.find(where);
    if (it != command->flags.end()) return it->second + ": " + e.message();
  }
  const auto it = common.find(where);
  return it == common.end() ? std::string(e.what()) : it->second + ": " + e.message();
}

// Throws the InputError that names `word` when it is none of `parent`'s subcommands, and says
// where a plumbing command lives when it is one given without `dev`.
void refuse_unknown(const CLI::App& parent, const std::string& word) {
  std::string names;
  for (const CLI::App* sub : parent.get_subcommands({})) {
    if (sub->get_name() == word) return;
    names += (names.empty() ? "" : ", ") + sub->get_name();
  }
  const auto command = antkit::cli::registry().find(word);
  if (command != antkit::cli::registry().end() && command->second.group == antkit::cli::Group::dev)
    throw antkit::kernel::InputError(
        "", "'" + word + "' is plumbing for the project's scripts: antkit dev " + word);
  throw antkit::kernel::InputError("",
                                   "unknown subcommand '" + word + "'; expected one of " + names);
}

} // namespace

int main(int argc, char** argv) {
  CLI::App app{"antkit: deterministic, verified kernels for ant-inspired robots that measure and "
               "cover space with markers",
               "antkit"};
  app.set_version_flag("--version", std::string("antkit ") + ANTKIT_VERSION);
  app.require_subcommand(1);
  // The user's commands; the plumbing ones are added under `antkit dev` by dev.cpp.
  for (const auto& [name, command] : antkit::cli::registry())
    if (command.group == antkit::cli::Group::user) command.registrar(app);
  refuse_empty_values(app);

  try {
    // A first word that is neither an option nor a subcommand: name it (CLI11 would only say that
    // a subcommand is required); the same for the word after `dev`.
    if (argc > 1 && argv[1][0] != '-') refuse_unknown(app, argv[1]);
    if (argc > 2 && argv[1] == std::string("dev") && argv[2][0] != '-')
      refuse_unknown(*app.get_subcommand("dev"), argv[2]);
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "antkit: error: " << e.what() << "\n(run `antkit --help` for usage)\n";
    return 2;
  } catch (const antkit::kernel::InputError& e) {
    std::cerr << "antkit: error: " << shown(e, app) << '\n';
    return 2;
  } catch (const antkit::cli::CheckFailed& e) {
    std::cerr << "antkit: check failed: " << e.what() << '\n';
    return 1;
  } catch (const antkit::cli::Interrupted& e) {
    std::cerr << "antkit: " << e.what() << '\n';
    return e.status();
  } catch (const std::exception& e) {
    // Not a bad input we recognised, and not a crash: report it as an internal error.
    std::cerr << "antkit: internal error: " << e.what() << '\n';
    return 3;
  }
  return 0;
}
