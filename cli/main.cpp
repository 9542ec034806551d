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
  for (const CLI::App* sub : app.get_subcommands()) { // the one that ran (none before parsing)
    const auto command = antkit::cli::registry().find(sub->get_name());
    if (command == antkit::cli::registry().end()) continue;
    const auto it = command->second.flags.find(where);
    if (it != command->second.flags.end()) return it->second + ": " + e.message();
  }
  const auto it = common.find(where);
  return it == common.end() ? std::string(e.what()) : it->second + ": " + e.message();
}

} // namespace

int main(int argc, char** argv) {
  CLI::App app{"antkit: deterministic, verified kernels for ant-inspired robots that measure and "
               "cover space with markers",
               "antkit"};
  app.set_version_flag("--version", std::string("antkit ") + ANTKIT_VERSION);
  app.require_subcommand(1);
  for (const auto& entry : antkit::cli::registry()) entry.second.registrar(app);
  refuse_empty_values(app);

  try {
    // A first word that is neither an option nor a subcommand: name it (CLI11 would only say that
    // a subcommand is required).
    if (argc > 1 && argv[1][0] != '-') {
      std::string names;
      bool known = false;
      for (const CLI::App* sub : app.get_subcommands({})) {
        known = known || sub->get_name() == argv[1];
        names += (names.empty() ? "" : ", ") + sub->get_name();
      }
      if (!known)
        throw antkit::kernel::InputError("", "unknown subcommand '" + std::string(argv[1]) +
                                                 "'; expected one of " + names);
    }
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
  } catch (const std::exception& e) {
    // Not a bad input we recognised, and not a crash: report it as an internal error.
    std::cerr << "antkit: internal error: " << e.what() << '\n';
    return 3;
  }
  return 0;
}
