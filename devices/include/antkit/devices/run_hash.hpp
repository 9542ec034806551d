#pragma once
// The per-step fold of a run into one hash: record() and replay() of every robot fold every step's
// number, observation, command and state hash, so equal runs have equal hashes.
#include <antkit/kernel/hash.hpp>
#include <cstdint>
#include <span>

namespace antkit::devices {

class RunHash {
public:
  void add(std::int64_t step, std::span<const std::int64_t> obs, std::span<const std::int64_t> cmd,
           std::uint64_t state) noexcept {
    hash_.add_i64(step).add_u32(static_cast<std::uint32_t>(obs.size()));
    for (const auto v : obs) hash_.add_i64(v);
    hash_.add_u32(static_cast<std::uint32_t>(cmd.size()));
    for (const auto v : cmd) hash_.add_i64(v);
    hash_.add_u64(state);
  }
  [[nodiscard]] std::uint64_t value() const noexcept { return hash_.finish(); }

private:
  kernel::TraceHash hash_;
};

} // namespace antkit::devices
