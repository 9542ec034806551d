// Invariants 1-5 of issue 3 on random maps (rapidcheck).
#include <antkit/kernel/input_error.hpp>
#include <antkit/stc/offline.hpp>
#include <antkit/stc/path_format.hpp>
#include <antkit/stc/world.hpp>
#include <antkit/testing/generators.hpp>
#include <antkit/testing/stc.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

using namespace antkit::stc;
namespace gen = antkit::testing::gen;

TEST_CASE("exact variants: invariants 1-4 on random maps - and all four give the same tour",
          "[stc][property]") {
  rc::prop("offline, online, ant and ant-edge", [] {
    const auto [map, start] = *gen::stc_case({.partial_cells = true, .start_in_free_cell = true});
    antkit::testing::StcTourChecker checker;
    const RunResult offline = run_stc(map, start, Variant::Offline);
    const auto check = checker.check_exact(map, start, offline.path);
    RC_ASSERT(check.describe() == "ok");
    RC_ASSERT(offline.closed && offline.returned_to_start && offline.repeats == 0);
    RC_ASSERT(offline.covered == offline.reachable_subcells);
    for (Variant v : {Variant::Online, Variant::Ant, Variant::AntEdge}) {
      const RunResult r = run_stc(map, start, v);
      const auto same =
          antkit::testing::check_same_tour(offline.path, r.path, std::string(variant_name(v)));
      RC_ASSERT(same.describe() == "ok");
      RC_ASSERT(r.hash == offline.hash);
      RC_ASSERT(r.closed && !r.refused);
    }
  });
}

TEST_CASE("full: every reachable free sub-cell at least once - moves 4-adjacent and free - ends at "
          "or next to the start - repeats reported right",
          "[stc][property]") {
  rc::prop("full", [] {
    const auto [map, start] = *gen::stc_case({.partial_cells = true, .start_in_free_cell = false});
    antkit::testing::StcTourChecker checker;
    const RunResult r = run_stc(map, start, Variant::Full);
    const auto check = checker.check_full(map, start, r.path, r.repeats);
    RC_ASSERT(check.describe() == "ok");
    RC_ASSERT(r.covered == r.reachable_subcells);
    RC_ASSERT(r.closed && r.returned_to_start);
    // Repeats are bounded: each part is crossed into at most once per child plus its own covering
    // walk, so at most 3 repeats per sub-cell.
    RC_ASSERT(r.repeats <= 3 * r.covered);
  });
}

TEST_CASE("marker noise: a noisy run never leaves the free sub-cells and its counts add up",
          "[stc][property]") {
  rc::prop("ant and ant-edge under noise", [] {
    const auto [map, start] = *gen::stc_case({.partial_cells = true, .start_in_free_cell = true});
    const auto ppm = *rc::gen::inRange<std::uint32_t>(0, 300'001);
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    for (Variant v : {Variant::Ant, Variant::AntEdge}) {
      RunOptions o;
      o.noise = {ppm, seed, 0};
      const RunResult r = run_stc(map, start, v, o);
      RC_ASSERT(!r.refused);
      RC_ASSERT(r.covered <= r.reachable_subcells);
      RC_ASSERT(r.covered + r.repeats == r.positions);
      for (std::size_t i = 1; i < r.path.size(); ++i) {
        const auto d = r.path[i] - r.path[i - 1];
        RC_ASSERT(std::abs(d.x) + std::abs(d.y) == 1);
        RC_ASSERT(map[r.path[i]] == antkit::kernel::Occupancy::Free);
      }
      RC_ASSERT(run_stc(map, start, v, o).hash == r.hash); // reproducible
    }
  });
}

TEST_CASE("exact variants: invariants 1-4 on mazes, rooms and combs", "[stc][property]") {
  rc::prop("offline and ant-edge on antkit::testing's structured maps", [] {
    const auto [map, start] =
        *gen::stc_case_from(gen::any_grid_map({.max_width = 12, .max_height = 12}));
    antkit::testing::StcTourChecker checker;
    for (Variant v : {Variant::Offline, Variant::AntEdge}) {
      const RunResult r = run_stc(map, start, v);
      const auto check = checker.check_exact(map, start, r.path);
      RC_ASSERT(check.describe() == "ok");
      RC_ASSERT(r.returned_to_start && r.repeats == 0);
    }
  });
}

TEST_CASE(
    "offline: the fast path gives the OfflineStc controller's tour, driven step by step - and "
    "every variant streams the positions it records",
    "[stc][property]") {
  rc::prop("fast path and controller", [] {
    const auto [map, start] = *gen::stc_case({.partial_cells = true, .start_in_free_cell = true});
    const RunResult fast = run_stc(map, start, Variant::Offline);
    StcWorld world;
    world.reset(map, start);
    OfflineStc controller(map, start);
    std::vector<SubCell> driven{start};
    for (Command c; (c = controller.step({})).move != Move::Stop;) {
      RC_ASSERT(world.apply(c));
      driven.push_back(world.position());
    }
    RC_ASSERT(fast.path == driven);
    RC_ASSERT(fast.positions == static_cast<std::int64_t>(driven.size()));
    RC_ASSERT(fast.covered == world.covered());
    RC_ASSERT(fast.repeats == world.repeats());
    for (const Variant v : kVariants) {
      RunOptions streamed;
      streamed.record_path = false;
      std::vector<SubCell> sunk;
      streamed.on_position = [&](SubCell s) { sunk.push_back(s); };
      const RunResult a = run_stc(map, start, v);
      const RunResult b = run_stc(map, start, v, streamed);
      RC_ASSERT(sunk == a.path);
      RC_ASSERT(b.path.empty());
      RC_ASSERT(b.hash == a.hash);
      RC_ASSERT(b.positions == a.positions);
      RC_ASSERT(b.covered == a.covered);
    }
  });
}

TEST_CASE("the binary path: decode(encode(tour)) is the tour, of every variant and length",
          "[stc][property]") {
  // path_format.hpp's Encoder (what `antkit stc --path-out F.bin` streams) against its decoder:
  // tours of every variant on random maps, cut at a random length so that every remainder of
  // moves mod 4 (the last byte's padding) occurs; and a non-adjacent move is refused.
  rc::prop("every variant, every prefix", [] {
    const auto [map, start] = *gen::stc_case({.partial_cells = true, .start_in_free_cell = true});
    const Variant v = *rc::gen::element(Variant::Offline, Variant::Online, Variant::Ant,
                                        Variant::AntEdge, Variant::Full);
    std::vector<antkit::kernel::Cell> tour = run_stc(map, start, v).path;
    RC_PRE(!tour.empty());
    tour.resize(*rc::gen::inRange<std::size_t>(1, tour.size() + 1));
    const std::string bytes = path_format::encode(map.width(), map.height(), tour);
    RC_ASSERT(bytes.size() == path_format::kHeaderBytes + (tour.size() - 1 + 3) / 4);
    const auto d = path_format::decode(bytes, "encoded", std::uint64_t{1} << 28);
    RC_ASSERT(d.width == map.width());
    RC_ASSERT(d.height == map.height());
    RC_ASSERT(d.start == tour.front());
    RC_ASSERT(d.path == tour);
    if (tour.size() >= 2) {
      auto jump = tour;
      jump.back() = {jump.back().x + 3, jump.back().y}; // never 4-adjacent to the one before
      RC_ASSERT_THROWS_AS(path_format::encode(map.width(), map.height(), jump),
                          antkit::kernel::InputError);
    }
  });
}
