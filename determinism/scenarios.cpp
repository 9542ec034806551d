// antkit_determinism's scenario tables (issue 16): what each golden scenario of
// determinism/golden.txt runs, over every controller family and body, and the teeth; the modes that
// run them are main.cpp's. Buffon's arenas are walls built with the kernel's own sine and cosine,
// grid maps are real maps from data/maps/movingai or come from the families' keyed generators. Only
// the kernel, the algorithms, the map readers and the marker-floor robot's integer camera, floor
// and pilot: see main.cpp.
#include "scenarios.hpp"

#include <antkit/algorithms/units.hpp>
#include <antkit/buffon/mcu_encode.hpp>
#include <antkit/buffon/measurement.hpp>
#include <antkit/buffon/two_markers.hpp>
#include <antkit/devices/stc_floor/floor.hpp>
#include <antkit/devices/stc_floor/pilot.hpp>
#include <antkit/kernel/angle.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/los/explore.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/stc/mcu_input.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/uniform/coverage.hpp>
#include <antkit/uniform/scenario.hpp>
#include <antkit/uniform/wanderer_mcu_encode.hpp>
#include <antkit/uniform/world.hpp>
#include <array>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace antkit::determinism {

namespace {

using kernel::Cell;
using kernel::Fx;
using kernel::FxPoint;
using kernel::FxSegment;
using kernel::Occupancy;
using kernel::OccupancyGrid;

// ---- bodies and maps ----

// A regular 64-gon of radius r around the origin: the circle arena of paper 000 (d = 2r).
std::vector<FxSegment> polygon_walls(std::int32_t r) {
  std::vector<FxPoint> v;
  for (std::int32_t k = 0; k < 64; ++k) {
    const auto a = kernel::Angle::from_turns(k, 64);
    v.push_back({Fx::from_int(r) * kernel::cos(a), Fx::from_int(r) * kernel::sin(a)});
  }
  std::vector<FxSegment> walls;
  for (std::size_t k = 0; k < v.size(); ++k) walls.push_back({v[k], v[(k + 1) % v.size()]});
  return walls;
}

// An 8 x 8 square with a 2 x 2 square pillar near its top.
std::vector<FxSegment> square_with_pillar() {
  const auto box = [](std::int32_t x0, std::int32_t y0, std::int32_t x1, std::int32_t y1) {
    const FxPoint a{Fx::from_int(x0), Fx::from_int(y0)}, b{Fx::from_int(x1), Fx::from_int(y0)},
        c{Fx::from_int(x1), Fx::from_int(y1)}, d{Fx::from_int(x0), Fx::from_int(y1)};
    return std::vector<FxSegment>{{a, b}, {b, c}, {c, d}, {d, a}};
  };
  auto walls = box(0, 0, 8, 8);
  for (const auto& w : box(3, 5, 5, 7)) walls.push_back(w);
  return walls;
}

std::string cell_text(Cell c) {
  return std::to_string(c.x) + "," + std::to_string(c.y);
}

// ---- scenarios ----

constexpr std::uint64_t kBuffonTrials = 4;

void add_buffon(std::vector<Scenario>& out) {
  const std::pair<const char*, std::vector<FxSegment> (*)()> arenas[] = {
      {"circle10", [] { return polygon_walls(5); }}, {"square-pillar", square_with_pillar}};
  for (const auto& [arena, walls] : arenas)
    for (const std::uint64_t seed : {std::uint64_t{1}, std::uint64_t{2}, std::uint64_t{3}})
      for (const bool precise : {false, true}) {
        const std::string name = std::string("buffon/") + arena + "/seed" + std::to_string(seed) +
                                 (precise ? "/precision0.5" : "");
        out.push_back(
            {name, [walls = walls, seed, precise](unsigned threads, Trace& trace) {
               const buffon::World world(walls());
               buffon::TrialParams p;
               p.seed = seed;
               p.steps = precise ? 12000 : 3000;
               p.precision_millionths = precise ? 500000 : 0;
               if (trace.on()) {
                 // Every visit of every trial, pose by pose (visit 2 to its full length:
                 // the online rule only decides where the hashed run stops reading it).
                 for (std::uint64_t t = 0; t < kBuffonTrials; ++t)
                   for (int visit = 1; visit <= 2; ++visit) {
                     kernel::TraceHash unused;
                     buffon::run_visit(world, p, t, visit, unused, [&](const buffon::Pose& q) {
                       trace.step("trial " + std::to_string(t) + " visit " + std::to_string(visit) +
                                  " x " + std::to_string(q.position.x.raw()) + " y " +
                                  std::to_string(q.position.y.raw()) + " heading " +
                                  std::to_string(q.heading.raw()));
                       return true;
                     });
                   }
               }
               kernel::TraceHash all;
               for (const auto& r : buffon::run_trials(world, p, kBuffonTrials, threads))
                 all.add_u64(r.hash);
               return all.finish();
             }});
      }
  // Issue 17's rules on seed 1 of each arena at P = 0.5: the online first visit (self-crossings and
  // the pilot's exact test decide where visit 1 ends) and two markers (one walk, exact floor roots
  // seeded by binary64 for the piece lengths, the pair's table and its exact test).
  for (const auto& [arena, walls] : arenas)
    for (const bool markers : {false, true}) {
      const std::string name =
          std::string("buffon/") + arena + "/seed1/" + (markers ? "markers0.5" : "online0.5");
      out.push_back(
          {name, [walls = walls, markers](unsigned threads, Trace& trace) {
             const buffon::World world(walls());
             buffon::TrialParams p;
             // Small budgets: the arenas are tiny, so the trails are dense and every step tests
             // many pairs (the -O0 and qemu builds of the matrix pay for each).
             p.precision_millionths = 500000;
             p.total_steps = 20000;
             p.online_first_visit = !markers;
             if (trace.on()) {
               // The walks pose by pose to their caps (the rules only decide where the
               // hashed runs stop reading them).
               for (std::uint64_t t = 0; t < kBuffonTrials; ++t)
                 for (const int visit : markers ? std::vector<int>{3} : std::vector<int>{1, 2}) {
                   kernel::TraceHash unused;
                   buffon::TrialParams q = p;
                   q.steps = 10000;
                   buffon::run_visit(world, q, t, visit, unused, [&](const buffon::Pose& pose) {
                     trace.step("trial " + std::to_string(t) + " visit " + std::to_string(visit) +
                                " x " + std::to_string(pose.position.x.raw()) + " y " +
                                std::to_string(pose.position.y.raw()));
                     return true;
                   });
                 }
             }
             // Each trial's hash and both trails' lengths (the markers' lengths come from
             // exact roots seeded in binary64).
             std::vector<std::uint64_t> words(3 * kBuffonTrials);
             antkit::algorithms::for_each_unit(
                 kBuffonTrials, threads, [&](std::uint64_t t, unsigned) {
                   const auto r = markers ? buffon::run_two_marker_trial(world, p, t)
                                          : buffon::run_trial(world, p, t);
                   words[3 * t] = r.hash;
                   words[3 * t + 1] = static_cast<std::uint64_t>(r.length1_raw);
                   words[3 * t + 2] = static_cast<std::uint64_t>(r.length2_raw);
                 });
             kernel::TraceHash all;
             for (const std::uint64_t w : words) all.add_u64(w);
             return all.finish();
           }});
    }
}

void add_los(std::vector<Scenario>& out, MapShelf& shelf) {
  const char* maps[] = {"scattered25", "den312d", "brc202d"};
  for (const auto algo : {los::Algorithm::FastWallFollow, los::Algorithm::Frontier})
    for (int m = 0; m < 3; ++m) {
      const std::string name = std::string("los/") +
                               (algo == los::Algorithm::FastWallFollow ? "fwf" : "frontier") + "/" +
                               maps[m];
      out.push_back(
          {name, [algo, m, map = std::string(maps[m]), &shelf](unsigned, Trace& trace) {
             const OccupancyGrid grid =
                 m == 0 ? los::scattered_obstacles(25, 25, 5, 1, 0, {0, 24}) : shelf.get(map);
             const auto pair = los::start_pair(grid, los::default_start(grid));
             los::ExploreOptions o;
             o.algorithm = algo;
             los::TickHook hook;
             if (trace.on())
               hook = [&trace](const los::TwoRobotWorld& w, const los::ExplorationMap&,
                               const los::TeamObservation&, const los::TeamCommand& c) {
                 trace.step("A " + cell_text(w.position(0)) + " B " + cell_text(w.position(1)) +
                            " moves " + std::to_string(c.move[0]) + " " +
                            std::to_string(c.move[1]) + (c.finished ? " finished" : ""));
               };
             return los::explore(grid, pair[0], pair[1], o, hook).hash;
           }});
    }
}

// The sub-cell at the top-left of the first (row-major) 2 x 2 block of free cells in the largest
// 4-connected region of such blocks, so that every variant has the most of the map to cover.
Cell stc_start(const OccupancyGrid& g) {
  const std::int32_t w = g.width() / 2, h = g.height() / 2;
  const auto free_block = [&g](std::int32_t i, std::int32_t j) {
    for (std::int32_t d = 0; d < 4; ++d)
      if (g[{2 * i + d % 2, 2 * j + d / 2}] != Occupancy::Free) return false;
    return true;
  };
  std::vector<std::int32_t> label(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), -1);
  const auto at = [w](std::int32_t i, std::int32_t j) {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(w) + static_cast<std::size_t>(i);
  };
  std::size_t best_size = 0;
  Cell best{-1, -1};
  for (std::int32_t j = 0; j < h; ++j)
    for (std::int32_t i = 0; i < w; ++i) {
      if (label[at(i, j)] >= 0 || !free_block(i, j)) continue;
      std::vector<Cell> queue{{i, j}};
      label[at(i, j)] = 1;
      for (std::size_t q = 0; q < queue.size(); ++q)
        for (const Cell d : {Cell{1, 0}, Cell{-1, 0}, Cell{0, 1}, Cell{0, -1}}) {
          const Cell n{queue[q].x + d.x, queue[q].y + d.y};
          if (n.x < 0 || n.y < 0 || n.x >= w || n.y >= h || label[at(n.x, n.y)] >= 0 ||
              !free_block(n.x, n.y))
            continue;
          label[at(n.x, n.y)] = 1;
          queue.push_back(n);
        }
      if (queue.size() > best_size) {
        best_size = queue.size();
        best = {2 * i, 2 * j};
      }
    }
  if (best_size == 0) throw kernel::InputError("", "no free 2 x 2 block for STC to start on");
  return best;
}

constexpr std::array<const char*, 3> kStcMaps{"den312d", "warehouse-10-20-10-2-1", "ht_chantry"};
constexpr stc::NoiseModel kStcNoise{20000, 7, 0}; // the noisy scenarios' misreads

// "stc/VARIANT[-noise0.02]/MAP", the name of an STC scenario (and of its Cortex-M input).
std::string stc_scenario_name(stc::Variant variant, bool noisy, const char* map) {
  return "stc/" + std::string(stc::variant_name(variant)) + (noisy ? "-noise0.02" : "") + "/" + map;
}

void add_stc(std::vector<Scenario>& out, MapShelf& shelf) {
  for (const char* map : kStcMaps)
    for (const auto variant : stc::kVariants)
      for (const bool noisy : {false, true}) {
        if (noisy && variant != stc::Variant::Ant && variant != stc::Variant::AntEdge) continue;
        const std::string name = stc_scenario_name(variant, noisy, map);
        out.push_back({name, [variant, noisy, map, &shelf](unsigned, Trace& trace) {
                         const auto& grid = shelf.get(map);
                         stc::RunOptions o;
                         if (noisy) o.noise = kStcNoise;
                         o.record_path = trace.on();
                         const auto r = stc::run_stc(grid, stc_start(grid), variant, o);
                         for (const auto s : r.path) trace.step(cell_text({s.x, s.y}));
                         return r.hash;
                       }});
      }
}

// Paper 002's marker-floor robot (issue 14) through its rendered camera, with everything the
// emulator adds switched on: camera noise, a dark pattern, fading marks and a drifting turn rate
// that the rotation calibration follows. Every frame is integer arithmetic; the trace is the
// believed pose, T and the frame's digest per step.
void add_stc_floor(std::vector<Scenario>& out, MapShelf& shelf) {
  namespace sf = devices::stc_floor;
  for (const char* map : {"random-32-32-20"}) {
    out.push_back({"stc-floor/ant-edge/" + std::string(map), [map, &shelf](unsigned, Trace& trace) {
                     const auto& grid = shelf.get(map);
                     const auto start = stc_start(grid);
                     sf::FloorOptions f;
                     f.seed = 5;
                     f.noise = 20;
                     f.dark_offset = 30;
                     f.fade_half_life_ms = 120000;
                     f.drift_ppm_per_minute = 20000;
                     sf::FloorWorld world(grid, start, 1, f);
                     sf::SimulatedRobot robot(world);
                     const sf::Calibration c = sf::ideal_calibration();
                     const sf::View view(c, sf::default_view(c));
                     sf::PilotOptions o;
                     o.start = start;
                     o.max_steps = 2000;
                     const auto r = sf::run_pilot(robot, view, o, [&](const sf::PilotStep& s) {
                       if (trace.on())
                         trace.step(cell_text({s.position.x, s.position.y}) + " h" +
                                    std::to_string(s.heading) + " T" + std::to_string(s.turn_ms) +
                                    " " + kernel::hash_hex(s.frame));
                     });
                     kernel::TraceHash h;
                     h.add_u64(r.hash).add_i64(r.turn_ms).add_i64(world.clock_ms());
                     h.add_u64(stc::tour_hash(grid.width(), grid.height(), world.path()));
                     h.add_i64(world.max_offset()).add_u64(sf::frame_digest(world.capture(false)));
                     return h.finish();
                   }});
  }
}

// Three obstacle densities of Sturtevant's benchmark set: 0 %, 10 % and 20 %.
constexpr std::array<const char*, 3> kUniformMaps{"empty-32-32", "random-32-32-10",
                                                  "random-32-32-20"};
constexpr std::int32_t kUniformSensor = 3;
constexpr std::uint64_t kUniformTicks = 2000;

void add_uniform(std::vector<Scenario>& out, MapShelf& shelf) {
  using uniform::Algorithm;
  for (const auto algo : {Algorithm::RandomWanderer, Algorithm::PrimaryMovement, Algorithm::AStar,
                          Algorithm::CoordinatedAStar, Algorithm::Frontier})
    for (const std::size_t robots : {std::size_t{1}, std::size_t{4}})
      for (const char* map : kUniformMaps) {
        const std::string name = "uniform/" + std::string(uniform::algorithm_name(algo)) + "/" +
                                 std::to_string(robots) + "robots/" + map;
        out.push_back({name, [algo, robots, map, &shelf](unsigned, Trace& trace) {
                         const auto run = [&](std::uint64_t limit) {
                           const auto& grid = shelf.get(map);
                           uniform::CoverageWorld world(
                               grid, uniform::place_robots(grid, robots, {}, 1, 0), kUniformSensor);
                           auto r = uniform::run_coverage(world, algo, 1, 0, limit);
                           return std::make_pair(r, world.robots());
                         };
                         const auto [result, end] = run(kUniformTicks);
                         if (trace.on()) {
                           // run_coverage has no per-tick hook: tick k's state is the end of a run
                           // cut after k ticks (the controllers' streams are keyed, so every cut
                           // run is a prefix of the whole one).
                           for (std::uint64_t k = 0; k <= result.movements / robots + 1; ++k) {
                             const auto [r, poses] = run(k);
                             std::string s = "viewed " + std::to_string(r.viewed);
                             for (const auto& p : poses)
                               s += " " + cell_text(p.cell) + "/" + std::to_string(p.bearing);
                             trace.step(s);
                             if (r.stop != uniform::StopReason::TimeLimit) break;
                           }
                         }
                         return result.hash;
                       }});
      }
}

} // namespace

const OccupancyGrid& MapShelf::get(const std::string& name) {
  auto it = maps_.find(name);
  if (it != maps_.end()) return it->second;
  const std::string path = dir_ + "/movingai/" + name + ".map";
  std::ifstream in(path, std::ios::binary);
  if (!in) throw kernel::InputError(path, "cannot read (--maps names data/maps)");
  std::ostringstream text;
  text << in.rdbuf();
  return maps_.emplace(name, maps::parse_movingai(text.str(), path).cells).first->second;
}

std::vector<Scenario> scenarios(MapShelf& shelf) {
  std::vector<Scenario> all;
  add_buffon(all);
  add_los(all, shelf);
  add_stc(all, shelf);
  add_stc_floor(all, shelf);
  add_uniform(all, shelf);
  return all;
}

// The teeth: the first Buffon scenario's first trail hashed over the bytes of its coordinates as
// this CPU stores them, instead of the trace hash's defined little-endian order.
std::uint64_t native_endian_hash(Trace& trace) {
  const buffon::World world(polygon_walls(5));
  buffon::TrialParams p;
  p.seed = 1;
  p.steps = 3000;
  kernel::TraceHash unused, h;
  buffon::run_visit(world, p, 0, 1, unused, [&](const buffon::Pose& pose) {
    std::string bytes_hex;
    for (const std::int32_t v : {pose.position.x.raw(), pose.position.y.raw()}) {
      std::uint8_t bytes[4];
      std::memcpy(bytes, &v, 4);
      h.add_bytes(bytes);
      for (const auto b : bytes) {
        char two[3];
        std::snprintf(two, sizeof two, "%02x", b);
        bytes_hex += two;
      }
    }
    trace.step("bytes " + bytes_hex);
    return true;
  });
  return h.finish();
}

// The Cortex-M image's inputs for the scenarios it runs (main.cpp's --mcu-inputs writes them). Each
// input is its library writer's, from the scenario's own map, start, walls, body, seeds and limits:
// - STC (stc::mcu_input): ant and ant-edge with and without noise, and online, on the three maps;
// - Buffon on the square with a pillar (buffon::mcu_buffon_input, the digest program: four
//   trials; its 8 walls, buckets, raster, trail and crossing index fit the chip, the circle's 256
//   walls do not), the scenario's defaults (body, width) and 3000 steps per visit, seeds 1 to 3;
// - the step-turn wanderer alone (uniform::mcu_wanderer_input): uniform/rw/1robots on the three
//   maps, with add_uniform's placement, sensor 3, seed 1, trial 0 and 2000 ticks.
void for_each_mcu_input(MapShelf& shelf,
                        const std::function<void(const std::string& name,
                                                 const std::vector<std::uint8_t>& bytes)>& emit) {
  for (const char* map : kStcMaps)
    for (const auto variant : {stc::Variant::Ant, stc::Variant::AntEdge, stc::Variant::Online})
      for (const bool noisy : {false, true}) {
        if (noisy && variant == stc::Variant::Online) continue; // online reads no marks
        const auto& grid = shelf.get(map);
        emit(stc_scenario_name(variant, noisy, map),
             stc::mcu_input(grid, stc_start(grid), variant, noisy ? kStcNoise : stc::NoiseModel{}));
      }
  const buffon::World pillar(square_with_pillar(), buffon::BodyParams{});
  for (const std::uint64_t seed : {std::uint64_t{1}, std::uint64_t{2}, std::uint64_t{3}}) {
    emit("buffon/square-pillar/seed" + std::to_string(seed),
         buffon::mcu_buffon_input(pillar, buffon::TrialParams{}.width, seed, 3000,
                                  buffon::McuBuffonProgram::Digest)
             .bytes);
  }
  for (const char* map : kUniformMaps) {
    const auto& grid = shelf.get(map);
    const uniform::CoverageWorld world(grid, uniform::place_robots(grid, 1, {}, 1, 0),
                                       kUniformSensor);
    emit("uniform/rw/1robots/" + std::string(map),
         uniform::mcu_wanderer_input(world, 1, 0, kUniformTicks).bytes);
  }
}

} // namespace antkit::determinism
