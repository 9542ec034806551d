// The emulators' shared set-up (emulate_serve.hpp).
#include "emulate_serve.hpp"

#include <antkit/kernel/input_error.hpp>

namespace antkit::devices::detail {

void refuse_floor_options(const EmulateOptions& o) {
  const std::string others = " is an option of the stc-floor robot";
  if (o.map) throw kernel::InputError("floor map", others);
  if (o.start) throw kernel::InputError("start sub-cell", others);
  if (o.heading) throw kernel::InputError("start heading", others);
  if (o.noise) throw kernel::InputError("camera noise", others);
  if (o.dark_offset) throw kernel::InputError("dark offset", others);
  if (o.fade_s) throw kernel::InputError("fade half-life", others);
  if (o.rotation_error) throw kernel::InputError("rotation error", others);
  if (o.drift) throw kernel::InputError("drift", others);
}

EmulatorOptions emulator_options(const EmulateOptions& o) {
  EmulatorOptions options;
  options.seed = o.seed;
  options.faults = parse_faults(o.faults);
  return options;
}

std::optional<TcpListener> listen_for(const EmulateOptions& o) {
  std::optional<TcpListener> listener;
  if (o.listen)
    listener.emplace(TcpListener::listen(parse_tcp_endpoint(*o.listen, "listen address", true),
                                         "listen address"));
  return listener;
}

} // namespace antkit::devices::detail
