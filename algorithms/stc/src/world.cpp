#include <algorithm>
#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/full.hpp>
#include <antkit/stc/mcu_input.hpp>
#include <antkit/stc/offline.hpp>
#include <antkit/stc/world.hpp>
#include <string>
#include <vector>

namespace antkit::stc {

std::string_view variant_name(Variant v) noexcept {
  switch (v) {
  case Variant::Offline:
    return "offline";
  case Variant::Online:
    return "online";
  case Variant::Ant:
    return "ant";
  case Variant::AntEdge:
    return "ant-edge";
  case Variant::Full:
    return "full";
  }
  return "?";
}

std::optional<Variant> parse_variant(std::string_view name) noexcept {
  for (Variant v : kVariants)
    if (variant_name(v) == name) return v;
  return std::nullopt;
}

void fill_free_bits(const kernel::OccupancyGrid& map, std::span<std::uint8_t> bits) noexcept {
  const FloorSize size = floor_size(map.width(), map.height());
  const std::int32_t w = 2 * size.shape.cells_x;
  std::fill(bits.begin(), bits.end(), std::uint8_t{0});
  for (std::int32_t y = 0; y < 2 * size.shape.cells_y; ++y)
    for (std::int32_t x = 0; x < w; ++x)
      if (map[{x, y}] == kernel::Occupancy::Free) {
        const auto k =
            static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
        bits[k >> 3] = static_cast<std::uint8_t>(bits[k >> 3] | (1u << (k & 7)));
      }
}

void StcWorld::reset(const kernel::OccupancyGrid& map, SubCell start, NoiseModel noise,
                     Marker marker) {
  const FloorSize size = floor_size(map.width(), map.height());
  free_bits_.resize(size.bit_bytes);
  fill_free_bits(map, free_bits_);
  entered_bits_.resize(size.bit_bytes);
  marks_.resize(size.cells);
  edges_.resize(size.cells);
  floor_.reset(map.width(), map.height(),
               {free_bits_.data(), entered_bits_.data(), marks_.data(), edges_.data()}, start,
               noise, marker);
}

std::int64_t StcWorld::reachable_subcells(bool whole_cells) {
  queue_.clear();
  const CellGridShape shape = floor_.shape();
  const SubCell position = floor_.position();
  if (whole_cells) {
    scratch_.assign(
        static_cast<std::size_t>(shape.cells_x) * static_cast<std::size_t>(shape.cells_y), 0);
    auto at = [&](Cell c) {
      return static_cast<std::size_t>(c.y) * static_cast<std::size_t>(shape.cells_x) +
             static_cast<std::size_t>(c.x);
    };
    const Cell root = cell_of(position);
    scratch_[at(root)] = 1;
    queue_.push_back(root);
    for (std::size_t i = 0; i < queue_.size(); ++i)
      for (int d = 0; d < 4; ++d) {
        const Cell n = step(queue_[i], d);
        if (floor_.cell_free(n) && scratch_[at(n)] == 0) {
          scratch_[at(n)] = 1;
          queue_.push_back(n);
        }
      }
    return 4 * static_cast<std::int64_t>(queue_.size());
  }
  const auto w = static_cast<std::size_t>(2 * shape.cells_x);
  auto at = [&](SubCell s) {
    return static_cast<std::size_t>(s.y) * w + static_cast<std::size_t>(s.x);
  };
  scratch_.assign(w * static_cast<std::size_t>(2 * shape.cells_y), 0);
  scratch_[at(position)] = 1;
  queue_.push_back(position);
  for (std::size_t i = 0; i < queue_.size(); ++i)
    for (int d = 0; d < 4; ++d) {
      const SubCell n = step(queue_[i], d);
      if (floor_.sub_free(n) && scratch_[at(n)] == 0) {
        scratch_[at(n)] = 1;
        queue_.push_back(n);
      }
    }
  return static_cast<std::int64_t>(queue_.size());
}

void check_start(const kernel::OccupancyGrid& map, SubCell start, Variant variant) {
  const CellGridShape shape = cell_shape(map);
  const bool inside = start.x >= 0 && start.y >= 0 && shape.in_bounds(cell_of(start));
  if (inside && map[start] == kernel::Occupancy::Free &&
      (!is_exact(variant) || cell_free(map, cell_of(start))))
    return; // the common case builds no message
  const std::string at =
      "sub-cell (" + std::to_string(start.x) + ", " + std::to_string(start.y) + ")";
  if (start.x < 0 || start.y < 0 || !shape.in_bounds(cell_of(start)))
    throw kernel::InputError("start", at + " is outside the map's cells (" +
                                          std::to_string(2 * shape.cells_x) + " x " +
                                          std::to_string(2 * shape.cells_y) + " sub-cells)");
  if (map[start] != kernel::Occupancy::Free)
    throw kernel::InputError("start", at + " is inside an obstacle");
  if (is_exact(variant) && !cell_free(map, cell_of(start)))
    throw kernel::InputError("start", at + " lies in a cell with a blocked sub-cell; variant " +
                                          std::string(variant_name(variant)) +
                                          " needs a free start cell (variant full does not)");
}

namespace {} // namespace

std::uint64_t tour_hash(std::int32_t width, std::int32_t height, std::span<const SubCell> path) {
  if (path.empty()) {
    kernel::TraceHash h;
    h.add_u32(static_cast<std::uint32_t>(width)).add_u32(static_cast<std::uint32_t>(height));
    return h.finish();
  }
  kernel::TraceHash h = tour_hash_begin(width, height, path.front());
  for (const SubCell& s : path) tour_hash_add(h, s); // the start again first, as run_stc does
  return h.finish();
}

namespace {

template <class C, class Observe>
void drive(C& controller, Observe&& observe, StcWorld& world, RunResult& r, kernel::TraceHash& h,
           std::int64_t max_moves, bool record, const std::function<void(SubCell)>& sink) {
  const TourEnd end = drive_tour(controller, observe, world, h, max_moves, [&](SubCell s) {
    if (record) r.path.push_back(s);
    if (sink) sink(s);
  });
  r.positions += end.moves;
  r.closed = end.closed;
  r.refused = end.refused;
}

// Offline STC's fast path: SpanningTree's search emits the tour; the sub-cells entered are
// counted on a bitmap (so that covered and repeats are measured, not assumed).
RunResult run_offline(const kernel::OccupancyGrid& map, SubCell start, const RunOptions& options) {
  RunResult r;
  r.variant = Variant::Offline;
  r.reachable_subcells = reachable_subcells(map, start, Variant::Offline);
  kernel::TraceHash h = tour_hash_begin(map.width(), map.height(), start);
  const auto width = static_cast<std::uint64_t>(map.width());
  std::vector<std::uint64_t> entered((width * static_cast<std::uint64_t>(map.height()) + 63) / 64,
                                     0);
  if (options.record_path) r.path.reserve(static_cast<std::size_t>(r.reachable_subcells));
  SubCell last = start;
  const SpanningTree tree(map, start, [&](SubCell s) {
    tour_hash_add(h, s);
    ++r.positions;
    if (options.record_path) r.path.push_back(s);
    if (options.on_position) options.on_position(s);
    const std::uint64_t k =
        static_cast<std::uint64_t>(s.y) * width + static_cast<std::uint64_t>(s.x);
    const std::uint64_t bit = std::uint64_t{1} << (k & 63);
    if (entered[k >> 6] & bit)
      ++r.repeats;
    else
      ++r.covered;
    entered[k >> 6] |= bit;
    last = s;
  });
  r.closed = true;
  r.returned_to_start = last == start || adjacent(last, start);
  r.hash = h.finish();
  return r;
}

} // namespace

std::int64_t reachable_subcells(const kernel::OccupancyGrid& map, SubCell start, Variant variant) {
  const CellGridShape shape = cell_shape(map);
  std::vector<Cell> queue;
  if (is_exact(variant)) {
    kernel::Grid<std::uint8_t> cells = free_cells(map);
    const Cell root = cell_of(start);
    if (!shape.in_bounds(root) || cells[root] == 0) return 0;
    cells[root] = 2;
    queue.push_back(root);
    for (std::size_t i = 0; i < queue.size(); ++i)
      for (int d = 0; d < 4; ++d) {
        const Cell n = step(queue[i], d);
        if (shape.in_bounds(n) && cells[n] == 1) {
          cells[n] = 2;
          queue.push_back(n);
        }
      }
    return 4 * static_cast<std::int64_t>(queue.size());
  }
  const std::int32_t w = 2 * shape.cells_x, hgt = 2 * shape.cells_y;
  auto inside = [&](SubCell s) { return s.x >= 0 && s.y >= 0 && s.x < w && s.y < hgt; };
  if (!inside(start) || map[start] != kernel::Occupancy::Free) return 0;
  kernel::Grid<std::uint8_t> seen(map.width(), map.height(), 0);
  seen[start] = 1;
  queue.push_back(start);
  for (std::size_t i = 0; i < queue.size(); ++i)
    for (int d = 0; d < 4; ++d) {
      const SubCell n = step(queue[i], d);
      if (inside(n) && seen[n] == 0 && map[n] == kernel::Occupancy::Free) {
        seen[n] = 1;
        queue.push_back(n);
      }
    }
  return static_cast<std::int64_t>(queue.size());
}

RunResult run_stc(const kernel::OccupancyGrid& map, SubCell start, Variant variant,
                  const RunOptions& options) {
  StcWorld world;
  return run_stc(world, map, start, variant, options);
}

RunResult run_stc(StcWorld& world, const kernel::OccupancyGrid& map, SubCell start, Variant variant,
                  const RunOptions& options) {
  check_start(map, start, variant);
  if (variant == Variant::Offline) return run_offline(map, start, options);
  const bool marker = variant == Variant::Ant || variant == Variant::AntEdge;
  world.reset(map, start, marker ? options.noise : NoiseModel{},
              variant == Variant::AntEdge ? Marker::Edge : Marker::WholeSubCell);
  RunResult r;
  r.variant = variant;
  r.reachable_subcells = world.reachable_subcells(is_exact(variant));
  const std::int64_t max_moves =
      options.max_moves > 0
          ? options.max_moves
          : 16 * static_cast<std::int64_t>(map.width()) * static_cast<std::int64_t>(map.height()) +
                16;
  kernel::TraceHash h = tour_hash_begin(map.width(), map.height(), start);
  tour_hash_add(h, start);
  r.positions = 1;
  if (options.record_path) {
    if (is_exact(variant)) r.path.reserve(static_cast<std::size_t>(r.reachable_subcells));
    r.path.push_back(start);
  }
  if (options.on_position) options.on_position(start);
  const bool rec = options.record_path;
  const auto& sink = options.on_position;
  switch (variant) {
  case Variant::Offline: // run_offline above
    break;
  case Variant::Online: {
    OnlineStc c(quadrant_of(start));
    drive(
        c, [&] { return world.observe_cells(); }, world, r, h, max_moves, rec, sink);
    break;
  }
  case Variant::Ant: {
    AntStc c(quadrant_of(start));
    drive(
        c, [&] { return world.observe_marks(); }, world, r, h, max_moves, rec, sink);
    break;
  }
  case Variant::AntEdge: {
    AntEdgeStc c(quadrant_of(start));
    drive(
        c, [&] { return world.observe_edges(); }, world, r, h, max_moves, rec, sink);
    break;
  }
  case Variant::Full: {
    FullStc c(map, start);
    drive(
        c, [] { return FullStc::Observation{}; }, world, r, h, max_moves, rec, sink);
    break;
  }
  }
  r.covered = world.covered();
  r.repeats = world.repeats();
  const SubCell last = world.position();
  r.returned_to_start = r.closed && (last == start || adjacent(last, start));
  r.hash = h.finish();
  return r;
}

std::vector<std::uint8_t> mcu_input(const kernel::OccupancyGrid& map, SubCell start,
                                    Variant variant, NoiseModel noise) {
  if (variant != Variant::Ant && variant != Variant::AntEdge && variant != Variant::Online)
    throw kernel::InputError("variant", "the Cortex-M image runs ant, ant-edge and online; " +
                                            std::string(variant_name(variant)) +
                                            " runs on the host only (so far)");
  check_start(map, start, variant);
  McuRun run;
  run.variant = variant == Variant::Ant       ? McuVariant::Ant
                : variant == Variant::AntEdge ? McuVariant::AntEdge
                                              : McuVariant::Online;
  run.marker = variant == Variant::AntEdge ? Marker::Edge : Marker::WholeSubCell;
  run.width = map.width();
  run.height = map.height();
  const std::size_t need = mcu_bytes(run);
  if (map.width() > kMcuMaxSide || map.height() > kMcuMaxSide || need > kMcuFloorBytes)
    throw kernel::InputError(
        "map",
        std::to_string(map.width()) + " x " + std::to_string(map.height()) + " sub-cells need " +
            std::to_string(need) + " bytes of floor" +
            (variant == Variant::Online ? " and memory" : "") + " for " +
            std::string(variant_name(variant)) + " on the Cortex-M image, which has " +
            std::to_string(kMcuFloorBytes) + " (2 bits per sub-cell and " +
            (run.marker == Marker::Edge ? "2 bytes" : "1 byte") + " per cell" +
            (variant == Variant::Online ? ", and " +
                                              std::to_string(FixedCellMemory::bytes_for(
                                                  mcu_online_tiles(map.width(), map.height()))) +
                                              " for the tiles of cells online STC may see"
                                        : std::string()) +
            "; the STM32F405 has 128 KiB of RAM)");
  const FloorSize size = floor_size(map.width(), map.height());
  std::vector<std::uint8_t> out(kMcuHeaderBytes + size.bit_bytes, 0);
  auto put = [&](std::size_t at, std::uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i)
      out[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (8 * i));
  };
  for (std::size_t i = 0; i < 8; ++i) out[i] = static_cast<std::uint8_t>(kMcuMagic[i]);
  put(8, static_cast<std::uint32_t>(run.variant), 4);
  put(12, static_cast<std::uint32_t>(map.width()), 4);
  put(16, static_cast<std::uint32_t>(map.height()), 4);
  put(20, static_cast<std::uint32_t>(start.x), 4);
  put(24, static_cast<std::uint32_t>(start.y), 4);
  put(28, noise.ppm, 4);
  put(32, noise.seed, 8);
  put(40, noise.trial, 8);
  fill_free_bits(map, std::span(out).subspan(kMcuHeaderBytes));
  return out;
}

std::optional<SubCell> default_start(const kernel::OccupancyGrid& g, Variant variant) {
  const CellGridShape shape = cell_shape(g);
  const bool exact = is_exact(variant);
  // Nodes: cells (exact) or sub-cells of the cell area (full), in a byte array with a border of
  // closed nodes (no bounds checks in the search): 1 open, 0 closed or already labelled. Indices
  // fit 32 bits (at most (2^14 + 2)^2 nodes under the map cap).
  const std::size_t w = static_cast<std::size_t>(exact ? shape.cells_x : 2 * shape.cells_x);
  const std::size_t h = static_cast<std::size_t>(exact ? shape.cells_y : 2 * shape.cells_y);
  const std::size_t stride = w + 2;
  std::vector<std::uint8_t> open(stride * (h + 2), 0);
  for (std::size_t y = 0; y < h; ++y)
    for (std::size_t x = 0; x < w; ++x) {
      const Cell c{static_cast<std::int32_t>(x), static_cast<std::int32_t>(y)};
      open[(y + 1) * stride + x + 1] = exact                             ? cell_free(g, c)
                                       : g[c] == kernel::Occupancy::Free ? 1
                                                                         : 0;
    }
  const std::ptrdiff_t steps[4] = {1, -static_cast<std::ptrdiff_t>(stride), -1,
                                   static_cast<std::ptrdiff_t>(stride)};
  std::vector<std::uint32_t> queue;
  std::optional<std::size_t> best;
  std::size_t best_size = 0;
  for (std::size_t y = 1; y <= h; ++y)
    for (std::size_t k = y * stride + 1; k <= y * stride + w; ++k) {
      if (open[k] == 0) continue;
      queue.assign(1, static_cast<std::uint32_t>(k));
      open[k] = 0;
      for (std::size_t i = 0; i < queue.size(); ++i)
        for (const std::ptrdiff_t d : steps) {
          const auto n = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(queue[i]) + d);
          if (open[n] != 0) {
            open[n] = 0;
            queue.push_back(static_cast<std::uint32_t>(n));
          }
        }
      if (queue.size() > best_size) {
        best_size = queue.size();
        best = k;
      }
    }
  if (!best) return std::nullopt;
  const Cell c{static_cast<std::int32_t>(*best % stride - 1),
               static_cast<std::int32_t>(*best / stride - 1)};
  return exact ? subcell_of(c, 2) : c;
}

} // namespace antkit::stc
