#pragma once
// The controller contract (DESIGN.md): every algorithm is a deterministic state machine
//     Command Controller::step(const Observation&)
// separate from the body (simulator, robot, recorded log) that carries its commands out.
//
// A controller owns its state and its random stream, does no I/O, reads no clock and touches no
// global state. Two controllers built alike and fed the same observations emit the same commands,
// bit for bit. Observations and commands are small value types in kernel units.
#include <antkit/kernel/hash.hpp>
#include <concepts>
#include <cstdint>

namespace antkit::algorithms {

template <class C>
concept Controller = requires(C c, const typename C::Observation& o) {
  typename C::Observation;
  typename C::Command;
  { c.step(o) } -> std::same_as<typename C::Command>;
};

// A body: turns a command into motion and produces the next observation.
template <class B, class C>
concept Body = Controller<C> && requires(B b, const typename C::Command& cmd) {
  { b.observe() } -> std::same_as<typename C::Observation>;
  { b.apply(cmd) } -> std::same_as<void>;
};

// The library's version, for logs and JSON output: major * 10000 + minor * 100 + patch.
std::uint32_t version_number() noexcept;

} // namespace antkit::algorithms
