// The four families a campaign runs: how a case is drawn, which variants run on it, what breaks,
// and the command that replays a failure.
#include "batches.hpp"
#include "campaign_internal.hpp"
#include "shrink.hpp"

#include <antkit/buffon/measurement.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/segment.hpp>
#include <antkit/los/explore.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/testing/buffon.hpp>
#include <antkit/testing/generators.hpp>
#include <antkit/testing/los.hpp>
#include <antkit/testing/stc.hpp>
#include <antkit/testing/uniform.hpp>
#include <antkit/uniform/coverage.hpp>
#include <antkit/uniform/scenario.hpp>
#include <antkit/uniform/world.hpp>
#include <stdexcept>
#include <utility>

namespace antkit::campaign::detail {

using kernel::Cell;
using kernel::InputError;
using kernel::OccupancyGrid;
namespace gen = testing::gen;

namespace {

// The names a failure carries that are not variants: a planted rule, an exception. Their commands
// name the first variant run.
bool pseudo(const std::string& variant) {
  return variant == "extra rule" || variant == "exception";
}

std::string cell_text(Cell c) {
  return std::to_string(c.x) + "," + std::to_string(c.y);
}

gen::MapLimits grid_limits(const Options& o) {
  return {.min_width = 1, .max_width = o.max_width, .min_height = 1, .max_height = o.max_height};
}

// ---- STC ----

struct StcFamily {
  using Value = gen::StcCase;
  struct Context {
    stc::StcWorld world;
    testing::StcTourChecker checker;
    std::vector<Cell> reference;
  };
  std::vector<std::pair<std::string, stc::Variant>> variants;

  explicit StcFamily(const std::vector<std::string>& names) {
    for (const auto& n : names) variants.emplace_back(n, *stc::parse_variant(n));
  }
  static rc::Gen<Value> generator(const Options& o) {
    return rc::gen::oneOf(
        gen::stc_case(
            {.max_cells_x = o.max_width, .max_cells_y = o.max_height, .partial_cells = true}),
        gen::stc_case_from(gen::any_grid_map(grid_limits(o))));
  }
  Broken check(const Value& c, Context& x, std::uint64_t& moves) const {
    bool have_reference = false;
    std::uint64_t reference_hash = 0;
    for (const auto& [name, v] : variants) {
      stc::RunResult r = stc::run_stc(x.world, c.map, c.start, v);
      moves += static_cast<std::uint64_t>(r.positions);
      if (v == stc::Variant::Full) {
        const auto ch = x.checker.check_full(c.map, c.start, r.path, r.repeats);
        if (!ch.ok) return std::pair{name, ch.describe()};
        if (!r.closed || !r.returned_to_start || r.covered != r.reachable_subcells)
          return std::pair{name, std::string("the run reports an open or partial tour")};
        continue;
      }
      const auto ch = x.checker.check_exact(c.map, c.start, r.path);
      if (!ch.ok) return std::pair{name, ch.describe()};
      if (r.repeats != 0 || r.covered != r.reachable_subcells || !r.returned_to_start)
        return std::pair{name, std::string("the run's counts disagree with its tour")};
      if (!have_reference) {
        x.reference = std::move(r.path); // the first exact tour: the others must equal it
        reference_hash = r.hash;
        have_reference = true;
        continue;
      }
      const auto same = testing::check_same_tour(x.reference, r.path, name);
      if (!same.ok) return std::pair{name, same.describe()};
      if (r.hash != reference_hash)
        return std::pair{name, std::string("the same tour with another trace hash")};
    }
    return std::nullopt;
  }
  static const OccupancyGrid& map(const Value& c) { return c.map; }
  static Cell start(const Value& c) { return c.start; }
  // The extra rule of the tests is named after the first variant run.
  std::string command(const Value& c, const std::string& variant) const {
    return "antkit stc --map {MAP} --variant " +
           (pseudo(variant) ? variants.front().first : variant) + " --start " + cell_text(c.start);
  }
};

// ---- LOS ----

struct LosFamily {
  using Value = OccupancyGrid;
  struct Context {};
  std::vector<std::pair<std::string, los::ExploreOptions>> variants;

  explicit LosFamily(const std::vector<std::string>& names) {
    for (const auto& n : names) {
      los::ExploreOptions o;
      o.algorithm =
          n == "fast-wall-follow" ? los::Algorithm::FastWallFollow : los::Algorithm::Frontier;
      o.line_of_sight = n != "frontier-nolos";
      variants.emplace_back(n, o);
    }
  }
  static rc::Gen<Value> generator(const Options& o) { return gen::any_grid_map(grid_limits(o)); }
  static std::optional<std::array<Cell, 2>> starts(const Value& map) {
    try {
      return los::start_pair(map, los::default_start(map));
    } catch (const std::invalid_argument&) {
      return std::nullopt;
    }
  }
  Broken check(const Value& map, Context&, std::uint64_t& moves) const {
    const auto s = starts(map);
    if (!s) return std::nullopt;
    for (const auto& [name, options] : variants) {
      los::ExploreResult r;
      const std::string err = testing::check_run(map, (*s)[0], (*s)[1], options, &r);
      moves += 2 * r.steps;
      if (!err.empty()) return std::pair{name, err};
    }
    return std::nullopt;
  }
  static const OccupancyGrid& map(const Value& m) { return m; }
  static Cell start(const Value& m) {
    const auto s = starts(m);
    return s ? (*s)[0] : Cell{};
  }
  std::string command(const Value& m, const std::string& name) const {
    const std::string& variant = pseudo(name) ? variants.front().first : name;
    const std::string algo = variant == "fast-wall-follow" ? "fast-wall-follow" : "frontier";
    return "antkit explore --map {MAP} --algo " + algo +
           (variant == "frontier-nolos" ? " --los off" : "") + " --start " + cell_text(start(m));
  }
};

// ---- Uniform coverage ----

struct UniformCase {
  OccupancyGrid map;
  std::size_t robots = 1;
  std::int32_t sensor = 1;
  std::uint64_t seed = 1;
};

struct UniformFamily {
  using Value = UniformCase;
  struct Context {};
  std::vector<std::pair<std::string, uniform::Algorithm>> variants;

  explicit UniformFamily(const std::vector<std::string>& names) {
    for (const auto& n : names) variants.emplace_back(n, *uniform::parse_algorithm(n));
  }
  static rc::Gen<Value> generator(const Options& o) {
    return rc::gen::exec([l = grid_limits(o)] {
      UniformCase c;
      c.map = *gen::any_grid_map(l);
      c.robots = *rc::gen::inRange<std::size_t>(1, 5);
      c.sensor = *rc::gen::inRange<std::int32_t>(1, 7);
      c.seed = *rc::gen::inRange<std::uint64_t>(1, std::uint64_t{1} << 32);
      return c;
    });
  }
  static std::uint64_t limit(const Value& c) {
    return 4 * static_cast<std::uint64_t>(c.map.width()) *
               static_cast<std::uint64_t>(c.map.height()) +
           64;
  }
  Broken check(const Value& c, Context&, std::uint64_t& moves) const {
    std::vector<uniform::Pose> poses;
    try {
      poses = uniform::place_robots(c.map, c.robots, std::nullopt, c.seed, 0);
    } catch (const InputError&) {
      return std::nullopt; // too few free cells for the robots: nothing to run
    }
    for (const auto& [name, algo] : variants) {
      uniform::CoverageWorld checked(c.map, poses, c.sensor);
      const auto ch = testing::check_uniform_run(checked, algo, c.seed, 0, limit(c));
      moves += ch.result.movements * c.robots;
      if (!ch.ok) return std::pair{name, ch.what};
      uniform::CoverageWorld plain(c.map, poses, c.sensor);
      const auto r = uniform::run_coverage(plain, algo, c.seed, 0, limit(c));
      if (r.hash != ch.result.hash || r.movements != ch.result.movements ||
          r.viewed != ch.result.viewed)
        return std::pair{name, std::string("run_coverage and the checked replay differ")};
    }
    return std::nullopt;
  }
  static const OccupancyGrid& map(const Value& c) { return c.map; }
  static Cell start(const Value& c) {
    try {
      return uniform::place_robots(c.map, c.robots, std::nullopt, c.seed, 0).front().cell;
    } catch (const InputError&) {
      return {};
    }
  }
  std::string command(const Value& c, const std::string& variant) const {
    return "antkit cover --map {MAP} --algo " +
           (pseudo(variant) ? variants.front().first : variant) + " --robots " +
           std::to_string(c.robots) + " --sensor " + std::to_string(c.sensor) + " --seed " +
           std::to_string(c.seed) + " --trial 0 --limit " + std::to_string(limit(c));
  }
};

// ---- Buffon ----

struct BuffonCase {
  gen::ArenaCase arena;
  std::int64_t steps;       // per visit (fixed, precision) or half the budget (online)
  std::int32_t width_milli; // the trail width in thousandths of a unit
  std::uint64_t seed;
};

struct BuffonFamily {
  using Value = BuffonCase;
  struct Context {};
  std::vector<std::string> variants;

  explicit BuffonFamily(std::vector<std::string> names) : variants(std::move(names)) {}
  static rc::Gen<Value> generator(const Options&) {
    return rc::gen::exec([] { // a braced list draws left to right
      return BuffonCase{*gen::arena_with_holes(), *rc::gen::inRange<std::int64_t>(10, 2001),
                        *rc::gen::inRange<std::int32_t>(50, 501),
                        *rc::gen::inRange<std::uint64_t>(1, std::uint64_t{1} << 32)};
    });
  }
  static buffon::TrialParams params(const Value& c, const std::string& variant) {
    buffon::TrialParams p;
    p.seed = c.seed;
    p.steps = c.steps;
    p.width = kernel::Fx::from_ratio(c.width_milli, 1000);
    p.keep_trails = true;
    if (variant != "fixed") {
      p.precision_millionths = 200000;
      p.visit2_steps = c.steps;
    }
    if (variant == "online") {
      p.online_first_visit = true;
      p.total_steps = 2 * c.steps;
    }
    return p;
  }
  Broken check(const Value& c, Context&, std::uint64_t& moves) const {
    const buffon::World world(c.arena.arena.walls_fx());
    for (const auto& name : variants) {
      buffon::TrialResult r;
      try {
        r = buffon::run_trial(world, params(c, name), 0);
      } catch (const InputError&) {
        // The paper's start (0.83 above the midpoint of the lowest wall) is not clear in this
        // arena: no trial to check (a vacuous case).
        return std::nullopt;
      }
      moves += static_cast<std::uint64_t>(r.steps1 + r.steps2);
      testing::BuffonBudget budget{c.steps, c.steps, name == "online" ? 2 * c.steps : 0};
      const auto ch = testing::check_buffon_trial(world, r, budget);
      if (!ch.ok) return std::pair{name, ch.describe()};
    }
    return std::nullopt;
  }
  static const OccupancyGrid& map(const Value&) {
    static const OccupancyGrid none;
    return none;
  }
  static Cell start(const Value&) { return {}; }
  std::string command(const Value& c, const std::string& name) const {
    const std::string& variant = pseudo(name) ? variants.front() : name;
    const std::string width = std::to_string(c.width_milli / 1000) + "." +
                              std::to_string(1000 + c.width_milli % 1000).substr(1);
    const std::string cmd = "antkit buffon --arena {MAP} --trials 1 --seed " +
                            std::to_string(c.seed) + " --width " + width;
    if (variant == "fixed") return cmd + " --steps " + std::to_string(c.steps);
    if (variant == "precision")
      return cmd + " --steps " + std::to_string(c.steps) + " --precision 0.2 --rule fixed " +
             "--max-steps2 " + std::to_string(c.steps);
    return cmd + " --precision 0.2 --rule online --max-steps " + std::to_string(2 * c.steps);
  }
};

} // namespace

template <>
std::string arena_text<BuffonFamily>(const BuffonCase& c) {
  return c.arena.wkt;
}

Result run_family_of(const Options& options, const algorithms::Runner& runner) {
  const auto names = options.variants.empty() ? family_variants(options.family) : options.variants;
  switch (options.family) {
  case Family::Stc:
    return run_family(StcFamily(names), options, runner);
  case Family::Los:
    return run_family(LosFamily(names), options, runner);
  case Family::Uniform:
    return run_family(UniformFamily(names), options, runner);
  case Family::Buffon:
    return run_family(BuffonFamily(names), options, runner);
  }
  return {};
}

} // namespace antkit::campaign::detail
