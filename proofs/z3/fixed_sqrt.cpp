// Z3 proof: the shipped fixed-point square root of fixed.hpp (fx_sqrt_raw<int32, int64, 16, 32>,
// what sqrt(Fx) instantiates, and fx_sqrt_raw<int64, int128, 32, 64>, sqrt of Q31.32) has no
// undefined behaviour for any a >= 0 and returns the nearest integer to sqrt(a 2^F).
//
//   sqrt.no_overflow       (Q15.16) the 24 unrolled branch-free iterations and the final rounding:
//                          every signed operation and shift is defined for every a >= 0.
//   sqrt.n_in_loop_domain  n = a 2^F satisfies isqrt_floor's precondition 0 <= n < 4 * 2^top.
//   sqrt.round.*           the rounding step after the loop, over the code's own expression: the
//                          loop's two results r and rest in fx_sqrt_raw's term are replaced by
//                          unknowns R and REST (the replacement is checked to remove every trace of
//                          the input a, so what is left is exactly the code after the loop), and
//                          under what the loop guarantees (fixed_sqrt_step.cpp: rest = n - r^2,
//                          0 <= rest <= 2r) the result is R + [REST > R], defined, and the nearest
//                          integer: raw^2 - raw < n <= raw^2 + raw, i.e. (raw - 1/2)^2 < n <
//                          (raw + 1/2)^2 (no tie is possible).
//   sqrt.nearest.*         over the integers: the lemmas that read those inequalities as "nearest"
//                          and bound R so that R + 1 fits.
//
// The square R^2 is a ghost SQ with n = SQ + REST, and raw^2 is written SQ or SQ + 2R + 1 by the
// case (proved over the integers as sqrt.nearest.expand): the bit-vector claims are linear.
// Teeth: the rule "round up when rest >= r" and the floor root r itself are refuted as nearest.
//
// Together with fixed_sqrt_step.cpp (the loop invariant, one symbolic iteration), this proves the
// documented rounding of sqrt for every a >= 0 in both formats.
#include "prove.hpp"

#include <antkit/kernel/fixed.hpp>
#include <functional>
#include <set>
#include <string>

using namespace antkit::proofs;
namespace kn = antkit::kernel;

namespace {

// Whether e contains the constant named `name` (a free input of the claim).
bool mentions(const z3::expr& e, const std::string& name, std::set<unsigned>& seen) {
  if (!e.is_app()) return false;
  const unsigned id = Z3_get_ast_id(e.ctx(), e);
  if (!seen.insert(id).second) return false;
  if (e.num_args() == 0) return e.decl().name().str() == name;
  for (unsigned i = 0; i < e.num_args(); ++i)
    if (mentions(e.arg(i), name, seen)) return true;
  return false;
}
bool mentions(const z3::expr& e, const std::string& name) {
  std::set<unsigned> seen;
  return mentions(e, name, seen);
}

template <class I, class W, int F, int N, class S>
bool rounding(Prover& p, Session& s, const std::string& fmt) {
  constexpr int top = ((N - 2 + F) / 2) * 2; // as fx_sqrt_raw computes it
  constexpr int m = top / 2 + 1;             // n < 2^(2m), so r < 2^m
  const std::string a_name = fmt + ".a";
  const I a = I::var(a_name);
  p.assume(a >= I(0));
  s.clear_obligations();
  const I raw = kn::fx_sqrt_raw<I, W, F, N>(a);
  const std::vector<Session::Obligation> all = s.obligations();
  s.clear_obligations();
  // The kernel's own prefix and loop, built again from the same calls: Z3 shares equal terms, so
  // r and rest below ARE the subterms of `raw` (checked: after the replacement, `a` is gone).
  require(a >= I(0), "fixed-point square root of a negative number");
  const I clamped = select(a < I(0), I(0), a);
  const W n = kn::ops::shl(kn::ops::widen<W>(clamped), F);
  const std::size_t prefix = s.obligations().size();
  W rest(0);
  const W r = kn::isqrt_floor<W, top>(n, rest);
  const std::size_t loop = s.obligations().size();
  bool same = loop <= all.size();
  for (std::size_t i = 0; same && i < loop; ++i)
    same = z3::eq(all[i].holds, s.obligations()[i].holds);
  s.clear_obligations();
  const W R = W::var(fmt + ".R"), REST = W::var(fmt + ".REST");
  z3::expr_vector from(s.ctx()), to(s.ctx());
  from.push_back(r.expr());
  from.push_back(rest.expr());
  to.push_back(R.expr());
  to.push_back(REST.expr());
  const I out(z3::expr(raw.expr()).substitute(from, to));
  if (!same || mentions(out.expr(), a_name)) {
    std::cout << "FAILED   " << fmt
              << ".sqrt.round: the rebuilt loop is not the kernel's (its terms do not match)\n";
    return false;
  }
  // Obligations: the prefix's (kept as they are), the loop's (proved by sqrt.no_overflow and by
  // fixed_sqrt_step.cpp's step claim under the invariant; dropped here), the tail's (on R, REST).
  for (std::size_t i = 0; i < prefix; ++i) s.oblige(all[i].what, all[i].holds);
  p.claim(fmt + ".sqrt.n_in_loop_domain (0 <= a 2^F < 4 * 2^top)",
          S(0) <= S(n) && S(n) < (S(1) << (top + 2)));
  s.clear_obligations(); // the claim's own (wide: nothing wraps)
  for (std::size_t i = loop; i < all.size(); ++i)
    s.oblige(all[i].what, z3::expr(all[i].holds).substitute(from, to));

  // What the loop guarantees (fixed_sqrt_step.cpp), with SQ the ghost for R^2, and the bound
  // R < 2^m that R^2 <= n < 2^(2m) implies (sqrt.nearest.bound).
  const S sR(R), sREST(REST), sn(n), SQ = S::var(fmt + ".SQ"), sout(out);
  {
    Session::Specification spec;
    p.assume(sn == SQ + sREST && S(0) <= sREST && sREST <= S(2) * sR && S(0) <= sR &&
             sR < (S(1) << m) && S(0) <= SQ);
  }
  Bool up(true), nearest(true), bad_nearest(true), floor_nearest(true);
  {
    Session::Specification spec;
    up = sREST > sR;
    // raw^2 by the case: R^2 or (R + 1)^2 = R^2 + 2R + 1 (sqrt.nearest.expand).
    const auto is_nearest = [&](const Bool& rounds_up) {
      const S v = select(rounds_up, sR + S(1), sR);
      const S vsq = select(rounds_up, SQ + S(2) * sR + S(1), SQ);
      // For v = 0 the lower side v - 1/2 < sqrt(n) holds whatever n (sqrt.nearest.meaning).
      return (v == S(0) || vsq - v < sn) && sn <= vsq + v;
    };
    nearest = is_nearest(sout == sR + S(1));
    bad_nearest = is_nearest(sREST >= sR);
    floor_nearest = is_nearest(Bool(false));
  }
  p.claim(fmt + ".sqrt.round.picks (raw = r + [rest > r], defined)",
          sout == select(up, sR + S(1), sR));
  p.claim(fmt + ".sqrt.round.nearest ((raw = 0 or raw^2 - raw < n) and n <= raw^2 + raw)", nearest);
  p.refute(fmt + ".sqrt.round: rounding up when rest >= r is not nearest", bad_nearest);
  p.refute(fmt + ".sqrt.round: the floor root is not always nearest", floor_nearest);
  p.reset_domain();
  return true;
}

void integer_lemmas(Prover& p, Session& s) {
  z3::context& c = s.ctx();
  const z3::expr R = c.int_const("R"), n = c.int_const("n"), v = c.int_const("v");
  p.claim_over_integers("sqrt.nearest.expand ((R + 1)^2 = R^2 + 2R + 1)",
                        (R + 1) * (R + 1) == R * R + 2 * R + 1);
  // |v - sqrt(n)| < 1/2 for integers v, n >= 0 reads v - 1/2 < sqrt(n) < v + 1/2. Its upper side
  // is n < (v + 1/2)^2 <=> 4n < (2v + 1)^2 <=> n <= v^2 + v; its lower side holds for v = 0 and for
  // v >= 1 is (v - 1/2)^2 < n <=> (2v - 1)^2 < 4n <=> v^2 - v < n. Both strict: no n is a tie.
  p.claim_over_integers(
      "sqrt.nearest.meaning (n <= v^2 + v <=> 4n < (2v + 1)^2; for v >= 1: "
      "v^2 - v < n <=> (2v - 1)^2 < 4n)",
      z3::implies(v >= 0,
                  (n <= v * v + v) == (4 * n < (2 * v + 1) * (2 * v + 1)) &&
                      z3::implies(v >= 1, (v * v - v < n) == ((2 * v - 1) * (2 * v - 1) < 4 * n))));
  for (int m : {24, 48}) {
    const z3::expr bound = c.int_val(std::to_string(1ULL << m).c_str());
    p.claim_over_integers("sqrt.nearest.bound (R >= 0, R^2 <= n < 2^" + std::to_string(2 * m) +
                              " => R < 2^" + std::to_string(m) + ")",
                          z3::implies(R >= 0 && R * R <= n && n < bound * bound, R < bound));
  }
}

} // namespace

int main() {
  Session s;
  Prover p(s);
  {
    const I32 a = I32::var("a");
    p.assume(a >= I32(0));
    const I32 raw = kn::fx_sqrt_raw<I32, I64, 16, 32>(a);
    p.no_undefined_behaviour("sqrt.no_overflow");
    // Teeth: a false claim about the same symbolic result must get a counterexample.
    p.refute("sqrt.teeth: raw = a", raw == a);
    p.reset_domain();
  }
  integer_lemmas(p, s);
  bool tied = rounding<I32, I64, 16, 32, Int<140, true>>(p, s, "q15.16");
  tied = rounding<I64, I128, 32, 64, Int<270, true>>(p, s, "q31.32") && tied;
  return p.result() == 0 && tied ? 0 : 1;
}
