// ROS 2 bags in the commands (bags.hpp).
#include <algorithm>
#include <antkit/buffon/crossing_counter.hpp>
#include <antkit/buffon/detector.hpp>
#include <antkit/buffon/estimate.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/buffon/stopping.hpp>
#include <antkit/commands/bags.hpp>
#include <antkit/commands/json.hpp>
#include <antkit/commands/options.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/segment.hpp>
#include <antkit/maps/map_io.hpp>
#include <climits>
#include <cmath>
#include <filesystem>
#include <limits>

namespace antkit::commands {

namespace {

using kernel::InputError;

nlohmann::json ns_json(const std::optional<std::uint64_t>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json maybe(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json interval(const devices::AreaInterval& ci) {
  return nlohmann::json::array({maybe(ci.lower), maybe(ci.upper)});
}

// The walk's poses as Q15.16 metres, and the length of that polyline (metres).
std::vector<kernel::FxPoint> fixed_walk(const io::bag::PoseTrack& track, double& length_m) {
  std::vector<kernel::FxPoint> points;
  points.reserve(track.poses.size());
  const auto raw = [&](double v) {
    const double r = std::nearbyint(v * 65536.0);
    if (!(r > INT32_MIN && r < INT32_MAX))
      throw InputError(track.path, "topic " + track.topic + ": a pose at " + std::to_string(v) +
                                       " m, outside the +/-32767 m that the crossing count reads");
    return kernel::Fx::from_raw(static_cast<std::int32_t>(r));
  };
  length_m = 0;
  for (const auto& p : track.poses) {
    points.push_back({raw(p.x), raw(p.y)});
    if (points.size() >= 2) {
      const auto& a = points[points.size() - 2];
      const auto& b = points.back();
      length_m += std::hypot(static_cast<double>(b.x.raw()) - a.x.raw(),
                             static_cast<double>(b.y.raw()) - a.y.raw()) /
                  65536.0;
    }
  }
  if (points.size() < 2)
    throw InputError(track.path, "topic " + track.topic + " has " + std::to_string(points.size()) +
                                     " pose(s): a walk needs two or more");
  return points;
}

} // namespace

io::bag::Stamp bag_stamp(const std::string& name, const std::string& where) {
  if (name == "bag") return io::bag::Stamp::bag;
  if (name == "header") return io::bag::Stamp::header;
  throw InputError(where, "'" + name + "' (expected bag or header)");
}

nlohmann::json bag_info_json(const io::bag::BagInfo& info) {
  nlohmann::json topics = nlohmann::json::array();
  for (const auto& t : info.topics)
    topics.push_back({{"topic", t.name},
                      {"type", t.type},
                      {"encoding", t.encoding},
                      {"messages", t.messages},
                      {"start_ns", ns_json(t.first_ns)},
                      {"end_ns", ns_json(t.last_ns)}});
  nlohmann::json j;
  j["bag"] = info.path;
  j["storage"] = std::string(io::bag::storage_name(info.storage));
  j["files"] = info.files;
  j["messages"] = info.messages;
  j["start_ns"] = ns_json(info.first_ns);
  j["end_ns"] = ns_json(info.last_ns);
  j["duration_s"] = info.first_ns
                        ? nlohmann::json(static_cast<double>(*info.last_ns - *info.first_ns) / 1e9)
                        : nlohmann::json(nullptr);
  j["topics"] = topics;
  return j;
}

BuffonFromBags buffon_from_bags(const std::string& bag1, const std::string& bag2,
                                const std::string& topic, double width_m, io::bag::Stamp stamp,
                                const std::string& child_frame, const std::string& arena,
                                const std::string& width_where) {
  if (!(width_m >= 0.01 && width_m <= 10))
    throw InputError(width_where, "the trail width must be in [0.01, 10] metres for bags");
  std::error_code ec;
  if (std::filesystem::equivalent(bag1, bag2, ec))
    throw InputError(bag2, "the same bag as " + bag1 + " (two walks are two bags)");
  BuffonFromBags out;
  out.walk1 = io::bag::read_poses(bag1, topic, stamp, child_frame);
  out.walk2 = io::bag::read_poses(bag2, topic, stamp, child_frame);
  const auto p1 = fixed_walk(out.walk1, out.length1_m);
  const auto p2 = fixed_walk(out.walk2, out.length2_m);

  // The kernel's exact count, as antkit's own logs get it (devices::buffon_from_logs counts the
  // same crossings step by step through the precision rule's monitor, below, for its variances).
  out.crossings_exact = kernel::count_proper_crossings(p1, p2);
  buffon::PrecisionMonitor monitor(buffon::kPrecisionDenominator / 10, p1.size() - 1);
  buffon::CrossingCounter counter(p1);
  std::vector<std::uint32_t> crossed;
  for (std::size_t i = 1; i < p2.size(); ++i) {
    crossed.clear();
    counter.add(p2[i - 1], p2[i], &crossed);
    for (const std::uint32_t segment : crossed) monitor.crossing(segment);
    monitor.end_step();
  }
  out.variance_visit1 = monitor.spread().visit1;
  out.variance_visit2 = monitor.spread().visit2;

  // BC: the simulator's detector along walk 2 over walk 1's band, as for logs.
  const auto width =
      kernel::Fx::from_raw(static_cast<std::int32_t>(std::nearbyint(width_m * 65536)));
  std::int64_t x0 = INT32_MAX, y0 = INT32_MAX, x1 = INT32_MIN, y1 = INT32_MIN;
  for (const auto* trail : {&p1, &p2})
    for (const auto& p : *trail) {
      x0 = std::min<std::int64_t>(x0, p.x.raw()), y0 = std::min<std::int64_t>(y0, p.y.raw());
      x1 = std::max<std::int64_t>(x1, p.x.raw()), y1 = std::max<std::int64_t>(y1, p.y.raw());
    }
  const std::int64_t margin = width.raw() + 65536;
  const auto clamp = [](std::int64_t v) {
    return kernel::Fx::from_raw(
        static_cast<std::int32_t>(std::clamp<std::int64_t>(v, INT32_MIN / 2, INT32_MAX / 2)));
  };
  buffon::PheromoneRaster raster({clamp(x0 - margin), clamp(y0 - margin)},
                                 {clamp(x1 + margin), clamp(y1 + margin)}, width);
  for (const auto& p : p1) raster.lay(p);
  buffon::CrossingDetector detector;
  for (const auto& p : p2)
    if (detector.update(raster.at(p))) ++out.bc;

  const auto l1 = static_cast<std::int64_t>(std::llround(out.length1_m * 65536.0));
  const auto l2 = static_cast<std::int64_t>(std::llround(out.length2_m * 65536.0));
  out.area_bc = buffon::closed_form_area(out.length1_m, out.length2_m, out.bc).area;
  out.estimate = devices::estimate_area(
      {l1, l2, out.crossings_exact, out.variance_visit1, out.variance_visit2, 0});
  if (!arena.empty()) {
    out.arena = arena;
    const double truth = arena_spec_area(arena, "--arena");
    out.area_true = truth;
    const auto e = devices::relative_errors(out.estimate, truth);
    out.relative_error = e.corrected;
    out.relative_error_raw = e.raw;
  }
  return out;
}

nlohmann::json buffon_from_bags_json(const BuffonFromBags& r, double width_m) {
  const auto walk = [](const io::bag::PoseTrack& t, double length_m) {
    return nlohmann::json{{"bag", t.path},
                          {"topic", t.topic},
                          {"type", t.type},
                          {"poses", t.poses.size()},
                          {"steps", t.poses.size() - 1},
                          {"length", length_m},
                          {"start_ns", t.poses.front().t_ns},
                          {"end_ns", t.poses.back().t_ns},
                          {"truncated", nullptr},
                          {"hash", nullptr}};
  };
  const auto& e = r.estimate;
  nlohmann::json j;
  j["robot"] = nullptr;
  j["diameter_m"] = nullptr;
  j["unit"] = "m";
  j["stamp"] = r.walk1.stamp == io::bag::Stamp::bag ? "bag" : "header";
  j["visit1"] = walk(r.walk1, r.length1_m);
  j["visit2"] = walk(r.walk2, r.length2_m);
  j["width"] = width_m;
  j["bc"] = r.bc;
  j["crossings_exact"] = r.crossings_exact;
  j["area"] = maybe(e.area_raw);
  j["area_m2"] = maybe(e.area_raw);
  j["area_bc"] = maybe(r.area_bc);
  j["area_bc_m2"] = maybe(r.area_bc);
  j["area_raw"] = maybe(e.area_raw);
  j["area_raw_ci"] = interval(e.raw_ci);
  j["area_corrected"] = maybe(e.area_corrected);
  j["area_corrected_m2"] = maybe(e.area_corrected);
  j["area_corrected_ci"] = interval(e.corrected_ci);
  j["area_corrected_ci_m2"] = interval(e.corrected_ci);
  j["erosion_factor"] = e.erosion_factor;
  j["wall_encounters"] = nullptr;
  j["variance_visit1"] = r.variance_visit1;
  j["variance_visit2"] = r.variance_visit2;
  j["arena"] = r.arena.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.arena);
  j["arena_source"] = r.arena.empty() ? nlohmann::json(nullptr) : nlohmann::json("--arena");
  j["area_true"] = maybe(r.area_true);
  j["area_true_m2"] = maybe(r.area_true);
  j["relative_error"] = maybe(r.relative_error);
  j["relative_error_raw"] = maybe(r.relative_error_raw);
  return j;
}

namespace {

// A point in map cells from the lower-left corner (x right, y up), through resolution and origin.
struct MapPoint {
  double x = 0, y = 0;
};

MapPoint to_map(const maps::GridMap& map, double x, double y) {
  const double dx = x - map.origin_x, dy = y - map.origin_y;
  const double c = std::cos(map.origin_yaw), s = std::sin(map.origin_yaw);
  return {(dx * c + dy * s) / map.resolution, (-dx * s + dy * c) / map.resolution};
}

} // namespace

std::optional<std::int64_t> StcBagCheck::violation_ns() const {
  const auto step = report.audit.first.step;
  if (report.audit.ok() || step < 0 || static_cast<std::size_t>(step) >= entered_ns.size())
    return std::nullopt;
  return entered_ns[static_cast<std::size_t>(step)];
}

std::vector<BagCell> bag_cells(const maps::GridMap& map, const io::bag::PoseTrack& track,
                               const std::string& map_file) {
  const std::int64_t width = map.cells.width(), height = map.cells.height();
  std::vector<BagCell> cells;
  const auto cell_of = [&](const io::bag::TimedPose& p, std::size_t i) {
    const MapPoint m = to_map(map, p.x, p.y);
    const double cx = std::floor(m.x), cy = std::floor(m.y);
    if (!(cx >= 0 && cx < static_cast<double>(width) && cy >= 0 &&
          cy < static_cast<double>(height)))
      throw InputError(track.path, "topic " + track.topic + ": pose " + std::to_string(i) +
                                       " (time " + std::to_string(p.t_ns) + " ns) at (" +
                                       std::to_string(p.x) + ", " + std::to_string(p.y) +
                                       ") m leaves the map " + map_file);
    return std::pair<std::int64_t, std::int64_t>{static_cast<std::int64_t>(cx),
                                                 static_cast<std::int64_t>(cy)};
  };
  const auto enter = [&](std::int64_t cx, std::int64_t cy, std::int64_t t) {
    cells.push_back({static_cast<std::int32_t>(cx), static_cast<std::int32_t>(height - 1 - cy), t});
  };
  const auto& poses = track.poses;
  if (poses.empty()) return cells;
  auto [cx, cy] = cell_of(poses[0], 0);
  enter(cx, cy, poses[0].t_ns);
  for (std::size_t i = 1; i < poses.size(); ++i) {
    const auto [ex, ey] = cell_of(poses[i], i);
    if (ex == cx && ey == cy) continue;
    // The cells the segment passes through (a grid traversal): at each step the axis whose next
    // cell boundary the segment reaches first; as many steps as the cells are apart, so that it
    // ends in the pose's cell whatever the rounding.
    const MapPoint a = to_map(map, poses[i - 1].x, poses[i - 1].y);
    const MapPoint b = to_map(map, poses[i].x, poses[i].y);
    const double dx = b.x - a.x, dy = b.y - a.y;
    const std::int64_t sx = ex > cx ? 1 : -1, sy = ey > cy ? 1 : -1;
    std::int64_t nx = std::abs(ex - cx), ny = std::abs(ey - cy);
    const auto boundary = [](double from, double cell, std::int64_t step, double d) {
      if (d == 0) return std::numeric_limits<double>::infinity();
      const double edge = step > 0 ? cell + 1 : cell;
      return (edge - from) / d;
    };
    const std::int64_t t0 = poses[i - 1].t_ns, t1 = poses[i].t_ns;
    while (nx + ny > 0) {
      const double tx = nx > 0 ? boundary(a.x, static_cast<double>(cx), sx, dx)
                               : std::numeric_limits<double>::infinity();
      const double ty = ny > 0 ? boundary(a.y, static_cast<double>(cy), sy, dy)
                               : std::numeric_limits<double>::infinity();
      double t = 0;
      if (ny == 0 || (nx > 0 && tx <= ty)) {
        cx += sx, --nx, t = tx;
      } else {
        cy += sy, --ny, t = ty;
      }
      t = std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 1.0;
      enter(cx, cy, t0 + static_cast<std::int64_t>(std::llround(static_cast<double>(t1 - t0) * t)));
    }
  }
  return cells;
}

StcBagCheck check_stc_bag(const std::string& map_file, const std::string& bag,
                          const std::string& topic, io::bag::Stamp stamp,
                          const std::string& child_frame, const testing::StcCheckRequest& request) {
  return check_stc_bag(maps::load_map(map_file), map_file, bag, topic, stamp, child_frame, request);
}

StcBagCheck check_stc_bag(maps::GridMap map, const std::string& map_file, const std::string& bag,
                          const std::string& topic, io::bag::Stamp stamp,
                          const std::string& child_frame, const testing::StcCheckRequest& request) {
  StcBagCheck out;
  out.track = io::bag::read_poses(bag, topic, stamp, child_frame);
  testing::TourFile tour;
  for (const auto& c : bag_cells(map, out.track, map_file)) {
    tour.path.push_back({c.x, c.y});
    out.entered_ns.push_back(c.t_ns);
  }
  out.report = testing::check_stc(std::move(map), tour, request);
  return out;
}

std::optional<std::int64_t> CoverBagCheck::violation_ns() const {
  const auto tick = report.audit.first_tick;
  if (report.audit.ok() || tick < 0 || static_cast<std::size_t>(tick) >= tick_ns.size())
    return std::nullopt;
  return tick_ns[static_cast<std::size_t>(tick)];
}

CoverBagCheck check_cover_bag(const std::string& map_file, const std::string& bag,
                              const std::vector<std::string>& topics, io::bag::Stamp stamp,
                              const std::string& child_frame, std::int64_t sensor) {
  testing::check_sensor_range(sensor);
  return check_cover_bag(maps::load_map(map_file), map_file, bag, topics, stamp, child_frame,
                         sensor);
}

CoverBagCheck check_cover_bag(const maps::GridMap& map, const std::string& map_file,
                              const std::string& bag, const std::vector<std::string>& topics,
                              io::bag::Stamp stamp, const std::string& child_frame,
                              std::int64_t sensor) {
  testing::check_sensor_range(sensor);
  if (topics.empty()) throw InputError("--topic", "no topic given: name one pose topic per robot");
  for (std::size_t i = 0; i < topics.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (topics[i] == topics[j])
        throw InputError("--topic", topics[i] + " given twice: one topic per robot");
  CoverBagCheck out;
  std::vector<std::vector<BagCell>> paths;
  for (const auto& topic : topics) {
    out.tracks.push_back(io::bag::read_poses(bag, topic, stamp, child_frame));
    paths.push_back(bag_cells(map, out.tracks.back(), map_file));
  }
  // Tick 0: every robot on its first pose's cell, facing its first pose's yaw (to the nearest
  // eighth, relative to the map's x axis). Then one tick per cell entered, in time order (ties in
  // topic order): that robot steps (a 4-neighbour step, facing the way it moved), the others stay.
  testing::CoverTrace trace;
  trace.robots = static_cast<std::int32_t>(topics.size());
  trace.sensor = static_cast<std::int32_t>(sensor);
  std::vector<kernel::Cell> at;
  std::vector<std::uint8_t> facing;
  std::int64_t start_ns = std::numeric_limits<std::int64_t>::max();
  for (std::size_t r = 0; r < paths.size(); ++r) {
    if (paths[r].empty())
      throw InputError(bag, "topic " + topics[r] + ": no poses, so no robot to check");
    at.push_back({paths[r][0].x, paths[r][0].y});
    const double eighths = (out.tracks[r].poses[0].yaw - map.origin_yaw) / (M_PI / 4);
    facing.push_back(static_cast<std::uint8_t>(((std::llround(eighths) % 8) + 8) % 8));
    start_ns = std::min(start_ns, paths[r][0].t_ns);
  }
  trace.cells.push_back(at);
  trace.bearings.push_back(facing);
  out.tick_ns.push_back(start_ns);
  std::vector<std::size_t> next(paths.size(), 1);
  for (;;) {
    std::size_t who = paths.size();
    for (std::size_t r = 0; r < paths.size(); ++r)
      if (next[r] < paths[r].size() &&
          (who == paths.size() || paths[r][next[r]].t_ns < paths[who][next[who]].t_ns))
        who = r;
    if (who == paths.size()) break;
    const BagCell& c = paths[who][next[who]++];
    const std::int32_t dx = c.x - at[who].x, dy = c.y - at[who].y;
    // A step of the traversal: east 0, north (up, y down) 2, west 4, south 6.
    facing[who] = static_cast<std::uint8_t>(dx > 0 ? 0 : dx < 0 ? 4 : dy < 0 ? 2 : 6);
    at[who] = {c.x, c.y};
    trace.cells.push_back(at);
    trace.bearings.push_back(facing);
    out.tick_ns.push_back(c.t_ns);
  }
  out.report = testing::check_cover(map.cells, trace, sensor, bag);
  return out;
}

nlohmann::json check_stc_bag_json(const StcBagCheck& c, const std::string& map) {
  nlohmann::json j = check_stc_json(c.report, map);
  j["bag"] = c.track.path;
  j["topic"] = c.track.topic;
  j["type"] = c.track.type;
  j["stamp"] = c.track.stamp == io::bag::Stamp::bag ? "bag" : "header";
  j["poses"] = c.track.poses.size();
  const auto t = c.violation_ns();
  j["first_violation_time_ns"] = t ? nlohmann::json(*t) : nlohmann::json(nullptr);
  return j;
}

nlohmann::json check_cover_bag_json(const CoverBagCheck& c, const std::string& map) {
  nlohmann::json j = check_cover_json(c.report, map);
  j["bag"] = c.tracks.empty() ? std::string() : c.tracks.front().path;
  j["stamp"] = c.tracks.empty() || c.tracks.front().stamp == io::bag::Stamp::bag ? "bag" : "header";
  nlohmann::json robots = nlohmann::json::array();
  for (const auto& t : c.tracks)
    robots.push_back({{"topic", t.topic}, {"type", t.type}, {"poses", t.poses.size()}});
  j["topics"] = robots;
  const auto t = c.violation_ns();
  j["first_violation_time_ns"] = t ? nlohmann::json(*t) : nlohmann::json(nullptr);
  return j;
}

} // namespace antkit::commands
