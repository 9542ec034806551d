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
#include "../z3/prove.hpp"

#include <cstring>

using namespace antkit::proofs;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: proof_teeth_harness contradictory-fact|unscoped-fact|scoped-keep|"
                 "impossible-path|sound\n";
    return 2;
  }
  const std::string mode = argv[1];
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
