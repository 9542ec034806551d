#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/full.hpp>
#include <antkit/stc/offline.hpp>
#include <antkit/stc/world.hpp>
#include <string>

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

void StcWorld::reset(const kernel::OccupancyGrid& map, SubCell start, NoiseModel noise) {
  width_ = map.width();
  height_ = map.height();
  shape_ = cell_shape(map);
  const auto n = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  free_.assign(n, 0);
  for (std::int32_t y = 0; y < 2 * shape_.cells_y; ++y)
    for (std::int32_t x = 0; x < 2 * shape_.cells_x; ++x)
      free_[index({x, y})] = map[{x, y}] == kernel::Occupancy::Free ? 1 : 0;
  cell_free_.assign(
      static_cast<std::size_t>(shape_.cells_x) * static_cast<std::size_t>(shape_.cells_y), 0);
  for (std::int32_t cy = 0; cy < shape_.cells_y; ++cy)
    for (std::int32_t cx = 0; cx < shape_.cells_x; ++cx) {
      bool all = true;
      for (int q = 0; q < 4; ++q) all = all && free_[index(subcell_of({cx, cy}, q))] != 0;
      cell_free_[static_cast<std::size_t>(cy) * static_cast<std::size_t>(shape_.cells_x) +
                 static_cast<std::size_t>(cx)] = all ? 1 : 0;
    }
  marks_.assign(n, 0);
  entered_.assign(n, 0);
  edges_.assign(static_cast<std::size_t>(width_ + 1) * static_cast<std::size_t>(height_) +
                    static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_ + 1),
                0);
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
    const auto cw = static_cast<std::size_t>(shape_.cells_x);
    auto at = [&](Cell c) {
      return static_cast<std::size_t>(c.y) * cw + static_cast<std::size_t>(c.x);
    };
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

std::size_t StcWorld::edge_index(SubCell s, int d) const noexcept {
  const auto w = static_cast<std::size_t>(width_);
  const auto x = static_cast<std::size_t>(s.x), y = static_cast<std::size_t>(s.y);
  const std::size_t horizontal = (w + 1) * static_cast<std::size_t>(height_);
  switch (d) {
  case 0:
    return y * (w + 1) + x + 1; // east: the vertical edge right of s
  case 1:
    return horizontal + y * w + x; // north: the horizontal edge above s
  case 2:
    return y * (w + 1) + x; // west
  default:
    return horizontal + (y + 1) * w + x; // south
  }
}

void StcWorld::light_edge(SubCell s, int d) noexcept {
  edges_[edge_index(s, d & 3)] = 1;
}

std::uint16_t StcWorld::cell_edges(Cell c) const noexcept {
  if (!shape_.in_bounds(c)) return 0;
  // The twelve edges of the cell, straight from the two edge arrays (edge_index() written out per
  // bit, because this runs for five cells every step of ant-edge). v(x, y): the vertical edge at
  // the west side of sub-cell (x, y); h(x, y): the horizontal edge at its north side.
  const auto w = static_cast<std::size_t>(width_);
  const auto x0 = static_cast<std::size_t>(2 * c.x), x1 = x0 + 1, x2 = x0 + 2;
  const auto y0 = static_cast<std::size_t>(2 * c.y);
  const std::size_t v0 = y0 * (w + 1), v1 = v0 + w + 1;
  const std::size_t h0 = (w + 1) * static_cast<std::size_t>(height_) + y0 * w, h1 = h0 + w,
                    h2 = h1 + w;
  const std::uint8_t* e = edges_.data();
  const unsigned bits =
      // cross boxes: SE's west, NE's south, NW's east, SW's north edge
      (e[v1 + x1] << 0) | (e[h1 + x1] << 1) | (e[v0 + x1] << 2) | (e[h1 + x0] << 3) |
      // turn boxes: SE's south, NE's east, NW's north, SW's west edge
      (e[h2 + x1] << 4) | (e[v0 + x2] << 5) | (e[h0 + x0] << 6) | (e[v1 + x0] << 7) |
      // the neighbours' turn boxes: SE's east, NE's north, NW's west, SW's south edge
      (e[v1 + x2] << 8) | (e[h0 + x1] << 9) | (e[v0 + x0] << 10) | (e[h2 + x0] << 11);
  return static_cast<std::uint16_t>(bits);
}

std::uint8_t StcWorld::cell_marks(Cell c) const noexcept {
  if (!shape_.in_bounds(c)) return 0;
  unsigned bits = 0;
  for (int q = 0; q < 4; ++q) bits |= static_cast<unsigned>(marks_[index(subcell_of(c, q))]) << q;
  return static_cast<std::uint8_t>(bits);
}

std::uint32_t StcWorld::misread(std::uint32_t bits, int count) noexcept {
  if (noise_.ppm == 0) return bits;
  for (int i = 0; i < count; ++i)
    if (stream_.chance(noise_.ppm, 1'000'000)) bits ^= 1u << i;
  return bits;
}

CellObservation StcWorld::observe_cells() const noexcept {
  const Cell c = cell_of(position_);
  unsigned bits = 0;
  for (int d = 0; d < 4; ++d) {
    const Cell n = step(c, d);
    if (shape_.in_bounds(n) &&
        cell_free_[static_cast<std::size_t>(n.y) * static_cast<std::size_t>(shape_.cells_x) +
                   static_cast<std::size_t>(n.x)] != 0)
      bits |= 1u << d;
  }
  return {static_cast<std::uint8_t>(bits)};
}

MarkObservation StcWorld::observe_marks() noexcept {
  const Cell c = cell_of(position_);
  MarkObservation o;
  o.free_neighbours = observe_cells().free_neighbours;
  o.here = static_cast<std::uint8_t>(misread(cell_marks(c), 4));
  for (int d = 0; d < 4; ++d)
    o.neighbour[static_cast<std::size_t>(d)] =
        static_cast<std::uint8_t>(misread(cell_marks(step(c, d)), 4));
  return o;
}

EdgeObservation StcWorld::observe_edges() noexcept {
  const Cell c = cell_of(position_);
  EdgeObservation o;
  o.free_neighbours = observe_cells().free_neighbours;
  o.here = static_cast<std::uint16_t>(misread(cell_edges(c), 12));
  for (int d = 0; d < 4; ++d)
    o.neighbour[static_cast<std::size_t>(d)] =
        static_cast<std::uint16_t>(misread(cell_edges(step(c, d)), 12));
  return o;
}

bool StcWorld::apply(const Command& command) noexcept {
  if (command.move == Move::Stop) return false;
  const int d = static_cast<int>(command.move);
  const SubCell target = step(position_, d);
  if (!sub_free(target)) return false;
  if (command.mark) {
    // Both markers are recorded; each marker variant reads only its own kind.
    marks_[index(position_)] = 1;
    light_edge(position_, opposite(d)); // the LEDs at the robot's back
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

template <class C, class Observe>
void drive(C& controller, Observe&& observe, StcWorld& world, RunResult& r, kernel::TraceHash& h,
           std::int64_t max_moves, bool record) {
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
  }
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
  const bool marker = variant == Variant::Ant || variant == Variant::AntEdge;
  world.reset(map, start, marker ? options.noise : NoiseModel{});
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
  const bool rec = options.record_path;
  switch (variant) {
  case Variant::Offline: {
    OfflineStc c(map, start);
    drive(
        c, [] { return OfflineStc::Observation{}; }, world, r, h, max_moves, rec);
    break;
  }
  case Variant::Online: {
    OnlineStc c(quadrant_of(start));
    drive(
        c, [&] { return world.observe_cells(); }, world, r, h, max_moves, rec);
    break;
  }
  case Variant::Ant: {
    AntStc c(quadrant_of(start));
    drive(
        c, [&] { return world.observe_marks(); }, world, r, h, max_moves, rec);
    break;
  }
  case Variant::AntEdge: {
    AntEdgeStc c(quadrant_of(start));
    drive(
        c, [&] { return world.observe_edges(); }, world, r, h, max_moves, rec);
    break;
  }
  case Variant::Full: {
    FullStc c(map, start);
    drive(
        c, [] { return FullStc::Observation{}; }, world, r, h, max_moves, rec);
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

} // namespace antkit::stc
