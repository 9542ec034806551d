// The Z3 harness's own teeth (issue 41): proof files whose context is contradictory must not pass.
// Each mode plants one way a proof can pass from nothing, and ctest requires the harness's refusal
// (its message and a non-zero exit); `sound` is the control, a proof that must still pass.
//
//   contradictory-fact   a fact that contradicts the domain, then `false` claimed: CONTEXT
//                        UNSATISFIABLE.
//   unscoped-fact        fixed_q31_div.cpp's old slip: a fact proved under b != 0 kept globally
//                        (Session::fact), then a b == 0 section: CONTEXT UNSATISFIABLE.
//   scoped-keep          the same, kept with Prover::keep (scoped to b != 0): the b == 0 section's
//                        `false` is now a plain counterexample (FAILED), not a vacuous pass.
//   impossible-path      a claim made only on a branch the domain cannot take: VACUOUS at result().
//   sound                the control: the same shapes done right pass.
//   cache                the proof cache (proof_cache.hpp), in a fresh directory: a proved claim
//                        is answered from it the second time, a false claim fails every time (a
//                        failure is never kept), and an entry whose key was edited is not used.
#include "../z3/prove.hpp"

#include <cstring>
#include <filesystem>

using namespace antkit::proofs;

namespace {

// The cache's teeth. Prints each expectation that fails; 0 when all hold.
int cache_teeth() {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("antkit-proof-cache-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  ::setenv("ANTKIT_PROOF_CACHE", dir.c_str(), 1); // before the first use of the process's cache
  ProofCache& cache = ProofCache::global();
  int bad = 0;
  const auto expect = [&](bool ok, const std::string& what) {
    std::cout << (ok ? "ok       " : "WRONG    ") << what << "\n";
    if (!ok) ++bad;
  };
  // One run of a small proof: a true claim and, when asked, a false one; its failures.
  const auto run = [&](bool with_false) {
    Session s;
    Prover p(s);
    const I32 x = I32::var("x");
    p.assume(x > I32(0) && x < I32(1000));
    p.claim("cache.true_claim", x + I32(1) > x);
    if (with_false) p.claim("cache.false_claim", x > I32(500));
    return p.result();
  };
  expect(cache.enabled() && cache.hits() == 0, "the cache starts empty and on");
  expect(run(false) == 0 && cache.hits() == 0, "first run: solved, nothing from the cache");
  const int after_first = cache.hits();
  expect(run(false) == 0 && cache.hits() > after_first,
         "second run of the same proof: answered from the cache");
  const int before_false = cache.hits();
  expect(run(true) != 0, "a false claim fails with a warm cache");
  const int after_false = cache.hits();
  expect(run(true) != 0, "and fails again: a failure is never kept");
  // The second false run may take only the true claim's and the context's answers from the cache.
  expect(cache.hits() - after_false == after_false - before_false,
         "the false claim's run used the cache no more the second time");
  // Edit every entry's key (as a query one character off would be): none may be used.
  for (const auto& e : fs::directory_iterator(dir)) {
    std::ofstream out(e.path(), std::ios::app | std::ios::binary);
    out << " ";
  }
  const int before_edit = cache.hits();
  expect(run(false) == 0 && cache.hits() == before_edit,
         "entries whose keys differ from the query by one character are not used");
  fs::remove_all(dir);
  std::cout << (bad == 0 ? "cache teeth: all held\n" : "cache teeth: FAILED\n");
  return bad == 0 ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: proof_teeth_harness contradictory-fact|unscoped-fact|scoped-keep|"
                 "impossible-path|sound|cache\n";
    return 2;
  }
  const std::string mode = argv[1];
  if (mode == "cache") return cache_teeth();
  Session s;
  Prover p(s);
  const I32 x = I32::var("x"), b = I32::var("b");
  if (mode == "contradictory-fact") {
    p.assume(x > I32(0));
    s.fact((x < I32(0)).expr());
    p.claim("teeth.false_from_a_contradictory_fact", Bool(false));
  } else if (mode == "unscoped-fact" || mode == "scoped-keep" || mode == "sound") {
    p.assume(b != I32(0));
    if (mode == "unscoped-fact") {
      if (p.claim("teeth.b_nonzero", b != I32(0))) s.fact((b != I32(0)).expr());
    } else {
      p.keep("teeth.b_nonzero", b != I32(0));
    }
    p.reset_domain();
    p.assume(b == I32(0));
    if (mode == "sound")
      p.claim("teeth.b_is_zero", b == I32(0));
    else
      p.claim("teeth.false_in_the_b_zero_section", Bool(false));
    if (mode == "sound") {
      // A path the domain excludes is skipped, and the claim still counts on the other one.
      p.reset_domain();
      p.assume(x > I32(5));
      for_each_path(s, [&] {
        if (x < I32(0))
          p.claim("teeth.on_both_paths", Bool(true));
        else
          p.claim("teeth.on_both_paths", x > I32(0));
      });
    }
  } else if (mode == "impossible-path") {
    p.assume(x > I32(5));
    for_each_path(s, [&] {
      if (x < I32(0)) p.claim("teeth.only_on_an_impossible_path", Bool(false));
    });
    p.claim("teeth.something_true", x > I32(0));
  } else {
    std::cerr << "unknown mode " << mode << "\n";
    return 2;
  }
  return p.result();
}
