// The emulators' shared set-up (emulate_serve.hpp).
#include "emulate_serve.hpp"

namespace antkit::devices::detail {

EmulatorOptions emulator_options(const EmulateOptions& o) {
  EmulatorOptions options;
  options.seed = o.seed;
  options.faults = parse_faults(o.device_options.texts("fault"));
  options.pace = o.device_options.on("pace");
  return options;
}

std::optional<TcpListener> listen_for(const EmulateOptions& o) {
  std::optional<TcpListener> listener;
  if (const auto listen = o.device_options.text("listen"))
    listener.emplace(
        TcpListener::listen(parse_tcp_endpoint(*listen, "listen address", true), "listen address"));
  return listener;
}

} // namespace antkit::devices::detail
