#pragma once
// Between antkit_determinism's scenario tables (scenarios.cpp: what each golden scenario runs) and
// its modes (main.cpp: hash, check, trace, list, the Cortex-M inputs, the STC tours, the teeth).
#include <antkit/kernel/grid.hpp>
#include <antkit/kernel/hash.hpp>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace antkit::determinism {

// The MovingAI maps of DIR/movingai (DIR is --maps, data/maps), each read once with the library's
// own parser.
class MapShelf {
public:
  explicit MapShelf(std::string dir) : dir_(std::move(dir)) {}
  const kernel::OccupancyGrid& get(const std::string& name);

private:
  std::string dir_;
  std::map<std::string, kernel::OccupancyGrid> maps_;
};

// A run's trace: per step, a chained hash of the states so far and the state itself. Off (no
// lines) when the scenario is only hashed.
class Trace {
public:
  explicit Trace(std::vector<std::string>* lines) : lines_(lines) {}
  [[nodiscard]] bool on() const noexcept { return lines_ != nullptr; }
  void step(const std::string& state) {
    if (lines_ == nullptr) return;
    kernel::TraceHash h;
    h.add_u64(chain_);
    for (const char c : state) h.add_u8(static_cast<std::uint8_t>(c));
    chain_ = h.finish();
    lines_->push_back(kernel::hash_hex(chain_) + " " + state);
  }

private:
  std::vector<std::string>* lines_;
  std::uint64_t chain_ = 0;
};

struct Scenario {
  std::string name;
  std::function<std::uint64_t(unsigned threads, Trace& trace)> run;
};

// Every golden scenario, in the order --list prints them (the maps are read on first run).
std::vector<Scenario> scenarios(MapShelf& shelf);

// The teeth: the first Buffon scenario's first trail hashed over the bytes of its coordinates as
// this CPU stores them, instead of the trace hash's defined little-endian order.
std::uint64_t native_endian_hash(Trace& trace);

// The Cortex-M image's input of every scenario it runs, in order: `emit(scenario name, bytes)`.
void for_each_mcu_input(MapShelf& shelf,
                        const std::function<void(const std::string& name,
                                                 const std::vector<std::uint8_t>& bytes)>& emit);

} // namespace antkit::determinism
