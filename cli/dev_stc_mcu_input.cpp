// `antkit dev stc-mcu-input` (plumbing for scripts/run-on-mcu.sh stc, issue 27): one ant, ant-edge
// or online STC run as the Cortex-M image's input (stc/mcu_input.hpp). The options are read and
// refused as `antkit stc` reads them (stc_options.hpp: the same start, the same messages, exit 2),
// and a map too large for the chip is refused with its size and the limit.
//
//   antkit dev stc-mcu-input --map FILE --variant ant|ant-edge|online [--start X,Y] [--noise P]
//                            [--seed S] --out FILE
#include "commands.hpp"
#include "stc_options.hpp"

#include <antkit/io/atomic_file.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/world.hpp>
#include <cstdint>
#include <iostream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace {

using antkit::kernel::InputError;

struct McuInputOptions {
  std::string map, variant, start, noise, out;
  std::uint64_t seed = 0;
};

void run(const McuInputOptions& o) {
  const auto r = antkit::cli::read_stc_request(o.map, o.variant, o.start, o.noise, o.seed);
  std::vector<std::uint8_t> bytes;
  try {
    bytes = antkit::stc::mcu_input(r.map.cells, r.start, r.variant, r.noise);
  } catch (const InputError& e) {
    // The writer's words: "variant" (one the chip does not run), "map" (too large for the chip),
    // else the start.
    const std::string where = e.where() == "variant" ? "--variant"
                              : e.where() == "map"   ? o.map
                              : o.start.empty()      ? o.map
                                                     : "--start";
    throw InputError(where, e.message());
  }
  antkit::io::write_file_atomic(
      o.out, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  std::cout << o.out << ": " << bytes.size() << " bytes, start " << r.start.x << "," << r.start.y
            << "\n";
}

void register_stc_mcu_input(CLI::App& app) {
  auto m = std::make_shared<McuInputOptions>();
  auto* mcu = app.add_subcommand(
      "stc-mcu-input", "Write one ant, ant-edge or online STC run as the Cortex-M image's input "
                       "(scripts/run-on-mcu.sh runs it under QEMU; stc/mcu_input.hpp)");
  mcu->add_option("--map", m->map, "The map (.map, .yaml or .txt)")->required();
  mcu->add_option("--variant", m->variant, "ant, ant-edge or online")->required();
  mcu->add_option("--start", m->start, "Start sub-cell X,Y (default as for `antkit stc`)");
  mcu->add_option("--noise", m->noise, "Mark misread probability (as for `antkit stc`)");
  mcu->add_option("--seed", m->seed, "Seed of the keyed noise stream (default 0)");
  mcu->add_option("--out", m->out, "The input file to write")->required();
  mcu->callback([m] { run(*m); });
}

const antkit::cli::DevRegistration dev_stc_mcu_input_registration{"stc-mcu-input",
                                                                  &register_stc_mcu_input};

} // namespace
