// antkit: the command-line front of the kit. Exit status: 0 success, 1 a failed check, 2 bad input
// (DESIGN.md, Errors).
#include "commands.hpp"
#include "output.hpp"

#include <antkit/kernel/input_error.hpp>
#include <exception>
#include <iostream>

namespace antkit::cli {
std::map<std::string, Registrar>& registry() {
  static std::map<std::string, Registrar> commands;
  return commands;
}
} // namespace antkit::cli

int main(int argc, char** argv) {
  CLI::App app{"antkit: deterministic, verified kernels for ant-inspired robots that measure and "
               "cover space with markers",
               "antkit"};
  app.set_version_flag("--version", std::string("antkit ") + ANTKIT_VERSION);
  app.require_subcommand(1);
  for (const auto& [name, registrar] : antkit::cli::registry()) registrar(app);

  try {
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
    std::cerr << "antkit: error: " << e.what() << '\n';
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
