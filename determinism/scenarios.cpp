// antkit_determinism: a fixed set of scenarios over every controller family and body, each
// printing its trace hash, for the determinism matrix (scripts/determinism.sh, issue 16). It links
// only antkit::algorithms and antkit::kernel, plus the map readers (geometry/src/map_*.cpp, which
// need no CGAL) and the marker-floor robot's integer camera, floor and
// pilot (devices/src/stc_floor_*.cpp but its calibration file: no JSON library), so that any
// compiler builds it and it cross-compiles to a big-endian CPU: Buffon's arenas are walls built
// with the kernel's own sine and cosine, grid maps are real maps from data/maps/movingai or
// come from the families' keyed generators.
//
//   antkit_determinism --maps DIR [--threads T]   prints "name hash" per scenario
//   antkit_determinism --maps DIR --check FILE [--threads T]
//                                                 exit 1 unless every scenario's hash is FILE's
//   antkit_determinism --maps DIR --trace NAME    one line per step of NAME's run: the step, a
//                                                 hash of the states up to it, and its state (for
//                                                 finding the first step where two builds part)
//   antkit_determinism --maps DIR --mcu-inputs DIR2
//                                                 writes the Cortex-M image's input of every
//                                                 scenario it runs (STC; Buffon on the square with
//                                                 a pillar; the wanderer alone) into DIR2, "name
//                                                 file" per line
//                                                 (the matrix's cortex-m4 configuration)
//   antkit_determinism --maps DIR --stc-tours     every shared map's STC tours (issue 27): per map
//                                                 of DIR/movingai and DIR/ros (name order) and
//                                                 variant the chip runs (ant, ant-edge, online),
//                                                 from `antkit stc`'s start: "stc-tour/<variant>/
//                                                 <file> hash covered repeats returned_to_start"
//   antkit_determinism --teeth native-endian [--check FILE | --trace teeth/native-endian]
//                                                 Buffon's first trail hashed over the bytes of its
//                                                 coordinates as this CPU stores them: FILE's hash
//                                                 on a little-endian CPU only (the matrix's teeth)
//
// Exit status: 0 all match, 1 a mismatch or a missing golden line, 2 bad usage or input.
#include <algorithm>
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
#include <antkit/stc/start.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/uniform/coverage.hpp>
#include <antkit/uniform/scenario.hpp>
#include <antkit/uniform/wanderer_mcu_encode.hpp>
#include <antkit/uniform/world.hpp>
#include <array>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace antkit;
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

// A MovingAI map of data/maps/movingai, read with the library's own parser.
class MapShelf {
public:
  explicit MapShelf(std::string dir) : dir_(std::move(dir)) {}
  const OccupancyGrid& get(const std::string& name) {
    auto it = maps_.find(name);
    if (it != maps_.end()) return it->second;
    const std::string path = dir_ + "/movingai/" + name + ".map";
    std::ifstream in(path, std::ios::binary);
    if (!in) throw kernel::InputError(path, "cannot read (--maps names data/maps)");
    std::ostringstream text;
    text << in.rdbuf();
    return maps_.emplace(name, maps::parse_movingai(text.str(), path).cells).first->second;
  }

private:
  std::string dir_;
  std::map<std::string, OccupancyGrid> maps_;
};

// ---- traces: per step, a chained hash of the states so far and the state itself ----

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

std::string cell_text(Cell c) {
  return std::to_string(c.x) + "," + std::to_string(c.y);
}

// ---- scenarios ----

struct Scenario {
  std::string name;
  std::function<std::uint64_t(unsigned threads, Trace& trace)> run;
};

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

// The Cortex-M image's inputs for the scenarios it runs, one file per scenario in `dir`, named by
// the scenario with '/' as '_'; prints "name file" per scenario. Each input is its library
// writer's, from the scenario's own map, start, walls, body, seeds and limits:
// - STC (stc::mcu_input): ant and ant-edge with and without noise, and online, on the three maps;
// - Buffon on the square with a pillar (buffon::mcu_buffon_input, the digest program: four
//   trials; its 8 walls, buckets, raster, trail and crossing index fit the chip, the circle's 256
//   walls do not), the scenario's defaults (body, width) and 3000 steps per visit, seeds 1 to 3;
// - the step-turn wanderer alone (uniform::mcu_wanderer_input): uniform/rw/1robots on the three
//   maps, with add_uniform's placement, sensor 3, seed 1, trial 0 and 2000 ticks.
void write_mcu_inputs(MapShelf& shelf, const std::string& dir) {
  const auto write = [&dir](const std::string& name, const std::vector<std::uint8_t>& bytes) {
    std::string file = dir + "/" + name;
    for (auto k = file.size() - name.size(); k < file.size(); ++k)
      if (file[k] == '/') file[k] = '_';
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
    if (!out.flush()) throw kernel::InputError(file, "cannot write");
    std::printf("%s %s\n", name.c_str(), file.c_str());
  };
  for (const char* map : kStcMaps)
    for (const auto variant : {stc::Variant::Ant, stc::Variant::AntEdge, stc::Variant::Online})
      for (const bool noisy : {false, true}) {
        if (noisy && variant == stc::Variant::Online) continue; // online reads no marks
        const auto& grid = shelf.get(map);
        write(
            stc_scenario_name(variant, noisy, map),
            stc::mcu_input(grid, stc_start(grid), variant, noisy ? kStcNoise : stc::NoiseModel{}));
      }
  const buffon::World pillar(square_with_pillar(), buffon::BodyParams{});
  for (const std::uint64_t seed : {std::uint64_t{1}, std::uint64_t{2}, std::uint64_t{3}}) {
    write("buffon/square-pillar/seed" + std::to_string(seed),
          buffon::mcu_buffon_input(pillar, buffon::TrialParams{}.width, seed, 3000,
                                   buffon::McuBuffonProgram::Digest)
              .bytes);
  }
  for (const char* map : kUniformMaps) {
    const auto& grid = shelf.get(map);
    const uniform::CoverageWorld world(grid, uniform::place_robots(grid, 1, {}, 1, 0),
                                       kUniformSensor);
    write("uniform/rw/1robots/" + std::string(map),
          uniform::mcu_wanderer_input(world, 1, 0, kUniformTicks).bytes);
  }
}

// `--stc-tours`: the tours `antkit stc --map F --variant V` makes on every shared map, for the
// variants the Cortex-M image runs, so that a build for another CPU (32-bit ARM Linux under
// qemu-user: scripts/determinism.sh) can be held to the host's on every map, not only the golden
// scenarios' three; determinism/check_stc_tours.sh holds this listing to `antkit stc` itself.
void print_stc_tours(const std::string& maps_dir) {
  std::vector<std::filesystem::path> files;
  for (const char* sub : {"movingai", "ros"})
    for (const auto& entry : std::filesystem::directory_iterator(maps_dir + "/" + sub)) {
      const auto ext = entry.path().extension();
      if (ext == ".map" || ext == ".yaml") files.push_back(entry.path());
    }
  std::sort(files.begin(), files.end());
  for (const auto& file : files) {
    const maps::GridMap map = maps::load_map(file);
    for (const auto variant : {stc::Variant::Ant, stc::Variant::AntEdge, stc::Variant::Online}) {
      const stc::SubCell start =
          stc::choose_start(map.cells, variant, std::nullopt, map.start, file.string());
      const stc::RunResult r = stc::run_stc(map.cells, start, variant);
      std::printf("stc-tour/%s/%s %s %lld %lld %s\n",
                  std::string(stc::variant_name(variant)).c_str(), file.filename().string().c_str(),
                  kernel::hash_hex(r.hash).c_str(), static_cast<long long>(r.covered),
                  static_cast<long long>(r.repeats), r.returned_to_start ? "true" : "false");
    }
  }
}

int usage(const std::string& why) {
  std::fprintf(stderr,
               "antkit_determinism: %s\nusage: antkit_determinism --maps DIR [--threads T] "
               "[--check FILE | --trace NAME | --list | --mcu-inputs DIR | --stc-tours]\n       "
               "antkit_determinism --teeth "
               "native-endian [--check FILE | --trace teeth/native-endian]\n",
               why.c_str());
  return 2;
}

int check_against(const std::map<std::string, std::string>& got, const std::string& file,
                  unsigned threads) {
  std::ifstream in(file);
  if (!in) {
    std::fprintf(stderr, "antkit_determinism: %s: cannot read\n", file.c_str());
    return 2;
  }
  std::size_t bad = 0, checked = 0, line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string name, hash, extra;
    if (!(fields >> name >> hash) || (fields >> extra) || hash.size() != 16) {
      std::fprintf(stderr, "antkit_determinism: %s:%zu: expected \"name hash\" (16 hex digits)\n",
                   file.c_str(), line_no);
      return 2;
    }
    const auto it = got.find(name);
    if (it == got.end()) continue; // another mode's line (the teeth, or the scenarios)
    ++checked;
    if (it->second != hash) {
      std::printf("MISMATCH %s: golden %s, this build %s\n", name.c_str(), hash.c_str(),
                  it->second.c_str());
      ++bad;
    }
  }
  if (checked != got.size()) {
    for (const auto& [name, hash] : got) {
      std::ifstream again(file);
      bool found = false;
      for (std::string line; !found && std::getline(again, line);)
        found = line.rfind(name + " ", 0) == 0;
      if (!found)
        std::printf("MISSING %s %s: no golden line in %s\n", name.c_str(), hash.c_str(),
                    file.c_str());
    }
    return 1;
  }
  std::printf("determinism: %zu of %zu scenarios match %s (threads %u)\n", checked - bad, checked,
              file.c_str(), threads);
  return bad == 0 ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
  unsigned threads = 1;
  std::string maps_dir, check, trace_name, teeth, mcu_dir;
  bool list = false, stc_tours = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--list" || a == "--stc-tours") {
      (a == "--list" ? list : stc_tours) = true;
      continue;
    }
    if (i + 1 >= argc) return usage(a + " needs a value");
    const std::string v = argv[++i];
    if (a == "--threads") {
      if (v.empty() || v.size() > 2 ||
          !std::all_of(v.begin(), v.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return usage("--threads: expected 1 to 64, got '" + v + "'");
      threads = static_cast<unsigned>(std::stoul(v));
      if (threads < 1 || threads > 64) return usage("--threads: expected 1 to 64, got " + v);
    } else if (a == "--maps") {
      maps_dir = v;
    } else if (a == "--check") {
      check = v;
    } else if (a == "--trace") {
      trace_name = v;
    } else if (a == "--teeth") {
      teeth = v;
    } else if (a == "--mcu-inputs") {
      mcu_dir = v;
    } else {
      return usage("unknown option " + a);
    }
  }
  if (!teeth.empty() && teeth != "native-endian")
    return usage("--teeth: only native-endian, got " + teeth);
  if (teeth.empty() && maps_dir.empty()) return usage("--maps DIR is required");
  try {
    std::map<std::string, std::string> got;
    if (!teeth.empty()) {
      std::vector<std::string> lines;
      Trace trace(trace_name.empty() ? nullptr : &lines);
      got["teeth/native-endian"] = kernel::hash_hex(native_endian_hash(trace));
      for (std::size_t k = 0; k < lines.size(); ++k) std::printf("%zu %s\n", k, lines[k].c_str());
      if (!trace_name.empty()) return 0;
    } else {
      if (stc_tours) {
        print_stc_tours(maps_dir);
        return 0;
      }
      MapShelf shelf(maps_dir);
      if (!mcu_dir.empty()) {
        write_mcu_inputs(shelf, mcu_dir);
        return 0;
      }
      const auto all = scenarios(shelf);
      if (list) {
        for (const auto& s : all) std::printf("%s\n", s.name.c_str());
        return 0;
      }
      if (!trace_name.empty()) {
        for (const auto& s : all)
          if (s.name == trace_name) {
            std::vector<std::string> lines;
            Trace trace(&lines);
            s.run(threads, trace);
            for (std::size_t k = 0; k < lines.size(); ++k)
              std::printf("%zu %s\n", k, lines[k].c_str());
            return 0;
          }
        return usage("no scenario " + trace_name + " (--list lists them)");
      }
      for (const auto& s : all) {
        Trace none(nullptr);
        got[s.name] = kernel::hash_hex(s.run(threads, none));
      }
    }
    if (check.empty()) {
      for (const auto& [name, hash] : got) std::printf("%s %s\n", name.c_str(), hash.c_str());
      return 0;
    }
    return check_against(got, check, threads);
  } catch (const kernel::InputError& e) {
    std::fprintf(stderr, "antkit_determinism: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "antkit_determinism: %s\n", e.what());
    return 2;
  }
}
