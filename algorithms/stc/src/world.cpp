#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/full.hpp>
#include <antkit/stc/offline.hpp>
#include <antkit/stc/world.hpp>
#include <string>
#include <vector>

namespace antkit::stc {

namespace {
constexpr unsigned kMarkFreeBit = 7;  // marks_: bits 0-3 the sub-cells' marks
constexpr unsigned kEdgeFreeBit = 15; // edges_: bits 0-11 the cell's edges (ant.hpp)
} // namespace

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

void StcWorld::reset(const kernel::OccupancyGrid& map, SubCell start, NoiseModel noise,
                     Marker marker) {
  marker_ = marker;
  width_ = map.width();
  height_ = map.height();
  shape_ = cell_shape(map);
  const auto n = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  free_.assign(n, 0);
  for (std::int32_t y = 0; y < 2 * shape_.cells_y; ++y)
    for (std::int32_t x = 0; x < 2 * shape_.cells_x; ++x)
      free_[index({x, y})] = map[{x, y}] == kernel::Occupancy::Free ? 1 : 0;
  // Cell arrays carry a border of one blocked cell, so that the neighbours of any cell of the map
  // can be read without a bounds check.
  stride_ = static_cast<std::size_t>(shape_.cells_x) + 2;
  offset_ = {1, 0 - stride_, 0 - std::size_t{1}, stride_};
  cell_free_.assign(stride_ * (static_cast<std::size_t>(shape_.cells_y) + 2), 0);
  for (std::int32_t cy = 0; cy < shape_.cells_y; ++cy)
    for (std::int32_t cx = 0; cx < shape_.cells_x; ++cx) {
      bool all = true;
      for (int q = 0; q < 4; ++q) all = all && free_[index(subcell_of({cx, cy}, q))] != 0;
      cell_free_[cell_index({cx, cy})] = all ? 1 : 0;
    }
  marks_.assign(cell_free_.size(), 0);
  edges_.assign(cell_free_.size(), 0);
  for (std::size_t i = 0; i < cell_free_.size(); ++i) {
    marks_[i] = static_cast<std::uint8_t>(cell_free_[i] << kMarkFreeBit);
    edges_[i] = static_cast<std::uint16_t>(cell_free_[i] << kEdgeFreeBit);
  }
  entered_.assign(n, 0);
  position_ = start;
  noise_ = noise;
  stream_ = kernel::Stream(noise.seed, kNoiseExperiment, noise.trial, 0, kNoisePurpose);
  covered_ = 0;
  repeats_ = 0;
  enter(start);
}

bool StcWorld::sub_free(SubCell s) const noexcept {
  return s.x >= 0 && s.y >= 0 && s.x < width_ && s.y < height_ && free_[index(s)] != 0;
}

void StcWorld::enter(SubCell s) noexcept {
  std::uint8_t& e = entered_[index(s)];
  if (e == 0) {
    ++covered_;
    e = 1;
  } else {
    ++repeats_;
  }
}

std::int64_t StcWorld::reachable_subcells(bool whole_cells) {
  queue_.clear();
  if (whole_cells) {
    scratch_.assign(cell_free_.size(), 0);
    auto at = [&](Cell c) { return cell_index(c); };
    const Cell root = cell_of(position_);
    scratch_[at(root)] = 1;
    queue_.push_back(root);
    for (std::size_t i = 0; i < queue_.size(); ++i)
      for (int d = 0; d < 4; ++d) {
        const Cell n = step(queue_[i], d);
        if (shape_.in_bounds(n) && cell_free_[at(n)] != 0 && scratch_[at(n)] == 0) {
          scratch_[at(n)] = 1;
          queue_.push_back(n);
        }
      }
    return 4 * static_cast<std::int64_t>(queue_.size());
  }
  scratch_.assign(free_.size(), 0);
  scratch_[index(position_)] = 1;
  queue_.push_back(position_);
  for (std::size_t i = 0; i < queue_.size(); ++i)
    for (int d = 0; d < 4; ++d) {
      const SubCell n = step(queue_[i], d);
      if (sub_free(n) && scratch_[index(n)] == 0) {
        scratch_[index(n)] = 1;
        queue_.push_back(n);
      }
    }
  return static_cast<std::int64_t>(queue_.size());
}

void StcWorld::light_edge(SubCell s, int d) noexcept {
  // The edge is kept in the 12-bit masks of the cells it belongs to (ant.hpp): an interior edge in
  // its cell only, an exterior edge in both cells it separates.
  d &= 3;
  const Cell c = cell_of(s);
  const int e = quadrant_of(s);
  if (!shape_.in_bounds(c)) return;
  auto light = [&](Cell cell, int bit) {
    if (shape_.in_bounds(cell)) edges_[cell_index(cell)] |= static_cast<std::uint16_t>(1u << bit);
  };
  if (d == dir_add(e, 2)) {
    light(c, e); // the cross box of e: interior, between e and e - 1
  } else if (d == dir_add(e, 1)) {
    light(c, dir_add(e, 1)); // interior, between e + 1 and e: the cross box of e + 1
  } else if (d == dir_add(e, 3)) {
    light(c, 4 + e);                      // the turn box of e...
    light(step(c, d), 8 + dir_add(e, 1)); // ...the own exterior edge of the sub-cell across
  } else {
    light(c, 8 + e);                      // e's own exterior edge (direction e)...
    light(step(c, d), 4 + dir_add(e, 3)); // ...the turn box of the sub-cell across
  }
}

std::uint16_t StcWorld::cell_edges(Cell c) const noexcept {
  return shape_.in_bounds(c) ? static_cast<std::uint16_t>(edges_[cell_index(c)] & 0x0FFFu)
                             : std::uint16_t{0};
}

std::uint8_t StcWorld::cell_marks(Cell c) const noexcept {
  return shape_.in_bounds(c) ? static_cast<std::uint8_t>(marks_[cell_index(c)] & 0x0Fu)
                             : std::uint8_t{0};
}

std::uint32_t StcWorld::misread(std::uint32_t bits, int count) noexcept {
  for (int i = 0; i < count; ++i)
    if (stream_.chance(noise_.ppm, 1'000'000)) bits ^= 1u << i;
  return bits;
}

CellObservation StcWorld::observe_cells() const noexcept {
  const std::size_t i = cell_index(cell_of(position_));
  unsigned bits = 0;
  for (std::size_t d = 0; d < 4; ++d)
    bits |= static_cast<unsigned>(cell_free_[i + offset_[d]]) << d;
  return {static_cast<std::uint8_t>(bits)};
}

MarkObservation StcWorld::observe_marks() noexcept {
  const std::size_t i = cell_index(cell_of(position_));
  MarkObservation o;
  o.here = static_cast<std::uint8_t>(marks_[i] & 0x0Fu);
  unsigned free = 0;
  for (std::size_t d = 0; d < 4; ++d) {
    const std::uint8_t m = marks_[i + offset_[d]];
    o.neighbour[d] = static_cast<std::uint8_t>(m & 0x0Fu);
    free |= static_cast<unsigned>(m >> kMarkFreeBit) << d;
  }
  o.free_neighbours = static_cast<std::uint8_t>(free);
  if (noise_.ppm != 0) {
    o.here = static_cast<std::uint8_t>(misread(o.here, 4));
    for (auto& m : o.neighbour) m = static_cast<std::uint8_t>(misread(m, 4));
  }
  return o;
}

// Written out beside observe_marks rather than shared as a template over the word type: the shared
// form measured 12 % slower for ant-edge on 4096^2 (21.2 -> 18.7 M sub-cells/s, same quiet run).
EdgeObservation StcWorld::observe_edges() noexcept {
  const std::size_t i = cell_index(cell_of(position_));
  EdgeObservation o;
  o.here = static_cast<std::uint16_t>(edges_[i] & 0x0FFFu);
  unsigned free = 0;
  for (std::size_t d = 0; d < 4; ++d) {
    const std::uint16_t e = edges_[i + offset_[d]];
    o.neighbour[d] = static_cast<std::uint16_t>(e & 0x0FFFu);
    free |= static_cast<unsigned>(e >> kEdgeFreeBit) << d;
  }
  o.free_neighbours = static_cast<std::uint8_t>(free);
  if (noise_.ppm != 0) {
    o.here = static_cast<std::uint16_t>(misread(o.here, 12));
    for (auto& m : o.neighbour) m = static_cast<std::uint16_t>(misread(m, 12));
  }
  return o;
}

bool StcWorld::apply(const Command& command) noexcept {
  if (command.move == Move::Stop) return false;
  const int d = static_cast<int>(command.move);
  const SubCell target = step(position_, d);
  if (!sub_free(target)) return false;
  if (command.mark) {
    if (marker_ == Marker::Edge)
      light_edge(position_, opposite(d)); // the LEDs at the robot's back
    else
      marks_[cell_index(cell_of(position_))] |=
          static_cast<std::uint8_t>(1u << quadrant_of(position_));
  }
  position_ = target;
  enter(target);
  return true;
}

namespace {

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

inline bool adjacent(SubCell a, SubCell b) noexcept {
  const Cell d = a - b;
  return (d.x == 0 && (d.y == 1 || d.y == -1)) || (d.y == 0 && (d.x == 1 || d.x == -1));
}

inline void hash_position(kernel::TraceHash& h, SubCell s) noexcept {
  // The same bytes as add_i32(x), add_i32(y); one aligned word.
  h.add_u64(std::uint64_t{static_cast<std::uint32_t>(s.x)} |
            (std::uint64_t{static_cast<std::uint32_t>(s.y)} << 32));
}

} // namespace

std::uint64_t tour_hash(std::int32_t width, std::int32_t height, std::span<const SubCell> path) {
  kernel::TraceHash h;
  h.add_u32(static_cast<std::uint32_t>(width)).add_u32(static_cast<std::uint32_t>(height));
  if (path.empty()) return h.finish();
  h.add_i32(path.front().x).add_i32(path.front().y);
  for (const SubCell& s : path) hash_position(h, s); // the start again first, as run_stc does
  return h.finish();
}

namespace {

template <class C, class Observe>
void drive(C& controller, Observe&& observe, StcWorld& world, RunResult& r, kernel::TraceHash& h,
           std::int64_t max_moves, bool record, const std::function<void(SubCell)>& sink) {
  for (std::int64_t m = 0; m < max_moves; ++m) {
    const Command c = controller.step(observe());
    if (c.move == Move::Stop) {
      r.closed = true;
      return;
    }
    if (!world.apply(c)) {
      r.refused = true;
      return;
    }
    const SubCell s = world.position();
    ++r.positions;
    hash_position(h, s);
    if (record) r.path.push_back(s);
    if (sink) sink(s);
  }
}

// Offline STC's fast path: SpanningTree's search emits the tour; the sub-cells entered are
// counted on a bitmap (so that covered and repeats are measured, not assumed).
RunResult run_offline(const kernel::OccupancyGrid& map, SubCell start, const RunOptions& options) {
  RunResult r;
  r.variant = Variant::Offline;
  r.reachable_subcells = reachable_subcells(map, start, Variant::Offline);
  kernel::TraceHash h;
  h.add_u32(static_cast<std::uint32_t>(map.width()))
      .add_u32(static_cast<std::uint32_t>(map.height()));
  h.add_i32(start.x).add_i32(start.y);
  const auto width = static_cast<std::uint64_t>(map.width());
  std::vector<std::uint64_t> entered((width * static_cast<std::uint64_t>(map.height()) + 63) / 64,
                                     0);
  if (options.record_path) r.path.reserve(static_cast<std::size_t>(r.reachable_subcells));
  SubCell last = start;
  const SpanningTree tree(map, start, [&](SubCell s) {
    hash_position(h, s);
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
  kernel::TraceHash h;
  h.add_u32(static_cast<std::uint32_t>(map.width()))
      .add_u32(static_cast<std::uint32_t>(map.height()));
  h.add_i32(start.x).add_i32(start.y);
  hash_position(h, start);
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
