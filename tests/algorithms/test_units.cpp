// run_units: unit order, thread and rank independence, failures named by unit. MPI ranks are
// simulated by threads that share a gather (the real mpirun is tested by mpi.reproduce.identical).
#include <antkit/algorithms/units.hpp>
#include <atomic>
#include <barrier>
#include <catch2/catch.hpp>
#include <mutex>
#include <stdexcept>
#include <thread>

using antkit::algorithms::Payload;
using antkit::algorithms::run_units;
using antkit::algorithms::Runner;

namespace {

Payload unit_payload(std::uint64_t u) {
  Payload p;
  p.put(u * u);
  p.put_d(1.0 / static_cast<double>(u + 1));
  p.put_text(std::string(u % 11, static_cast<char>('a' + u % 26)));
  return p;
}

// Runs run_units as `ranks` simulated ranks (one thread each) and returns rank 0's result.
std::vector<Payload> as_ranks(int ranks, unsigned threads, std::uint64_t count,
                              const std::function<Payload(std::uint64_t)>& unit,
                              std::string* rank0_error = nullptr) {
  std::barrier sync(ranks);
  std::mutex lock;
  std::vector<std::string> parts(static_cast<std::size_t>(ranks));
  std::vector<Payload> root;
  std::vector<std::thread> pool;
  for (int r = 0; r < ranks; ++r)
    pool.emplace_back([&, r] {
      Runner runner;
      runner.threads = threads;
      runner.rank = r;
      runner.ranks = ranks;
      runner.gather = [&, r](const std::string& mine) {
        {
          const std::lock_guard<std::mutex> held(lock);
          parts[static_cast<std::size_t>(r)] = mine;
        }
        sync.arrive_and_wait();
        return r == 0 ? parts : std::vector<std::string>{};
      };
      try {
        auto out = run_units(runner, "test", count, unit);
        if (r == 0)
          root = std::move(out);
        else
          CHECK(out.empty());
      } catch (const std::exception& e) {
        if (r == 0 && rank0_error) *rank0_error = e.what();
      }
    });
  for (auto& t : pool) t.join();
  return root;
}

} // namespace

TEST_CASE("run_units returns every unit's payload in unit order, whatever the threads and ranks") {
  const std::uint64_t count = 37;
  Runner one;
  const auto reference = run_units(one, "test", count, unit_payload);
  REQUIRE(reference.size() == count);
  for (std::uint64_t u = 0; u < count; ++u) {
    Payload p = reference[u];
    CHECK(p.get() == u * u);
    CHECK(p.get_d() == 1.0 / static_cast<double>(u + 1));
    CHECK(p.get_text() == std::string(u % 11, static_cast<char>('a' + u % 26)));
  }
  for (const unsigned threads : {1u, 2u, 5u}) {
    Runner r;
    r.threads = threads;
    const auto out = run_units(r, "test", count, unit_payload);
    REQUIRE(out.size() == count);
    for (std::uint64_t u = 0; u < count; ++u) CHECK(out[u].words() == reference[u].words());
  }
  for (const int ranks : {1, 2, 3, 4, 40}) {
    const auto out = as_ranks(ranks, 2, count, unit_payload);
    REQUIRE(out.size() == count);
    for (std::uint64_t u = 0; u < count; ++u) CHECK(out[u].words() == reference[u].words());
  }
  CHECK(run_units(one, "test", 0, unit_payload).empty());
}

TEST_CASE("run_units reports the first failing unit, after every rank has finished") {
  const auto failing = [](std::uint64_t u) {
    if (u == 9 || u == 22) throw std::runtime_error("unit " + std::to_string(u) + " broke");
    return unit_payload(u);
  };
  Runner r;
  r.threads = 3;
  try {
    (void)run_units(r, "stage", 30, failing);
    FAIL("no exception");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()) == "stage, unit 9: unit 9 broke");
  }
  for (const int ranks : {2, 3}) {
    std::string error;
    const auto out = as_ranks(ranks, 1, 30, failing, &error);
    CHECK(out.empty());
    CHECK(error == "test, unit 9: unit 9 broke");
  }
}

TEST_CASE("a payload refuses to be read past its end") {
  Payload p;
  p.put(1);
  CHECK(p.get() == 1);
  CHECK_THROWS_AS(p.get(), std::logic_error);
  Payload cut = Payload::of({100, 0});
  CHECK_THROWS_AS(cut.get_text(), std::logic_error);
}

TEST_CASE("for_each_unit runs every unit once, on workers numbered below the thread count") {
  for (const unsigned threads : {1u, 2u, 4u, 9u}) {
    std::vector<std::atomic<int>> runs(50);
    std::atomic<bool> worker_in_range{true};
    antkit::algorithms::for_each_unit(50, threads, [&](std::uint64_t u, unsigned t) {
      ++runs[u];
      if (t >= threads) worker_in_range = false;
    });
    for (const auto& r : runs) CHECK(r.load() == 1);
    CHECK(worker_in_range);
  }
  // The per-worker scratch the thread number is for: each worker's own slot, no lock.
  std::vector<std::uint64_t> sums(3, 0);
  antkit::algorithms::for_each_unit(1000, 3, [&](std::uint64_t u, unsigned t) { sums[t] += u; });
  CHECK(sums[0] + sums[1] + sums[2] == 999u * 1000u / 2u);
}

TEST_CASE("for_each_unit rethrows the lowest failing unit's exception, whatever the threads") {
  for (const unsigned threads : {1u, 2u, 3u, 8u}) {
    std::vector<std::atomic<int>> runs(40);
    try {
      antkit::algorithms::for_each_unit(40, threads, [&](std::uint64_t u, unsigned) {
        ++runs[u];
        if (u == 17 || u == 5 || u == 33) throw std::runtime_error(std::to_string(u));
      });
      FAIL("no exception");
    } catch (const std::runtime_error& e) {
      CHECK(std::string(e.what()) == "5");
    }
    for (std::size_t u = 0; u <= 5; ++u) CHECK(runs[u].load() == 1); // every unit up to it ran
  }
}
