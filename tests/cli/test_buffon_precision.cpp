// `antkit buffon --precision P` (issue 8, item 5): visit 2 ends at BC = N*, bad P exits 2.
#include "run_antkit.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

using antkit::test::run_antkit;

TEST_CASE("antkit buffon --precision stops visit 2 at the threshold count") {
  const auto r = run_antkit(
      "buffon --arena circle:d=20 --trials 3 --steps 50000 --precision 0.1 --format json");
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  const auto& s = j["summary"];
  for (const char* key : {"nbc_median", "nbc_q1", "nbc_q3", "area_closed_form_median", "precision",
                          "stop_bc", "dispersion", "stopped_at_bc", "length2_median"})
    CHECK(s.contains(key));
  CHECK(s["precision"].get<double>() == 0.1);
  const auto n = s["stop_bc"].get<std::uint64_t>();
  CHECK(n > 400); // N*(0.1, phi >= 1) >= 445
  CHECK(s["stopped_at_bc"].get<int>() == 3);
  for (const auto& t : j["trials"]) {
    CHECK(t["bc"].get<std::uint64_t>() == n); // ends at the step BC reaches N*
    CHECK(t["reached_precision"].get<bool>());
    CHECK(t["length2"].get<double>() < t["length1"].get<double>()); // stopped before --steps
  }
  // A finer precision needs a longer second visit.
  const auto fine = nlohmann::json::parse(
      run_antkit("buffon --arena circle:d=20 --trials 3 --steps 50000 --precision 0.05 "
                 "--format json")
          .out);
  CHECK(fine["summary"]["length2_median"].get<double>() > s["length2_median"].get<double>());
}

TEST_CASE("antkit buffon --precision: the --steps cap wins when N* is out of reach") {
  const auto r = run_antkit(
      "buffon --arena circle:d=20 --trials 2 --steps 2000 --precision 0.01 --format json");
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["summary"]["stopped_at_bc"].get<int>() == 0);
  for (const auto& t : j["trials"]) {
    CHECK_FALSE(t["reached_precision"].get<bool>());
    CHECK(t["bc"].get<std::uint64_t>() < j["summary"]["stop_bc"].get<std::uint64_t>());
  }
}

TEST_CASE("antkit buffon --precision without it keeps the output keys unchanged") {
  const auto j = nlohmann::json::parse(
      run_antkit("buffon --arena circle:d=20 --trials 1 --steps 1000 --format json").out);
  CHECK_FALSE(j["summary"].contains("precision"));
  CHECK_FALSE(j["trials"][0].contains("reached_precision"));
}

TEST_CASE("antkit buffon rejects a bad --precision with exit 2") {
  for (const std::string p : {"0", "1", "1.5", "-0.1", "abc", "0.0000001", "1e-2", "\"\""}) {
    const auto r = run_antkit("buffon --arena circle:d=20 --steps 100 --precision " + p);
    INFO(p << "\n" << r.err);
    CHECK(r.status == 2);
    CHECK(r.err.rfind("antkit: error: ", 0) == 0);
    CHECK(r.err.find("--precision") != std::string::npos);
    CHECK(r.out.empty());
  }
}
