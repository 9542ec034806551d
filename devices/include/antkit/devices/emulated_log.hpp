#pragma once
// A long, genuine hardware log made in seconds, without a port: what `antkit record` would log
// for `spec` driving a serial robot against its firmware emulator, the emulator answering each
// command in process (FirmwareEmulator::handle) instead of over a pseudo-terminal. For the tests
// and benchmarks of replay and export, which need logs of thousands of steps that replay
// identically.
#include <antkit/devices/controllers.hpp>
#include <antkit/devices/robot.hpp>
#include <antkit/kernel/segment.hpp>
#include <cstdint>
#include <string>
#include <vector>

namespace antkit::devices {

// The log's text (JSON Lines: the header, `steps` step records, the stop record "done"), as
// record() writes it: the identification and the start's exchanges at step 0 (schema 2), each
// step's proximity read, speed command and odometry read, then the safe stop and the speeds read
// back; t_ns = step x 100 us, the exchanges untimed. `walls` in body diameters (as for
// FirmwareEmulator); `arena` is the header's arena spec ("" for none). Throws kernel::InputError
// for an arena the emulator refuses and for a controller that refuses the spec.
std::string emulated_log(RobotKind robot, std::vector<kernel::FxSegment> walls,
                         const ControllerSpec& spec, std::int64_t steps,
                         const std::string& arena = "");

} // namespace antkit::devices
