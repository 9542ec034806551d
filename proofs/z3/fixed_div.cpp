// Z3 proof: the shipped fixed-point division fx_div_raw<I32, I64, 16> (fixed.hpp; what Fx's
// operator/ and Fx::from_ratio instantiate with machine integers) and its rounding kernel
// div_round_half_up<I64>, instantiated with Z3 bit-vectors.
//
//   fx.div.defined_in_domain   every operation is defined for b != 0 with the rounded quotient in
//                              range (fixed.hpp's domain); a quotient one past max() is caught.
//   fx.div.rounds_half_up      raw = floor(a 2^F / b + 1/2): with d = |b|, s = sign(b),
//                              raw 2d <= 2 s a 2^F + d < raw 2d + 2d, i.e.
//                              -1/2 ulp < raw - a 2^F / b <= 1/2 ulp (ties toward +infinity).
//   fx.div.by_zero_saturates   b == 0 gives max() for a >= 0 and min() for a < 0.
//
// How division is handled: z3_int.hpp abstracts the code's truncating t / d2 and t % d2 to unknowns
// q, r with C++'s definition q d2 + r = t, |r| < |d2|, r = 0 or r has t's sign (exact, 128 bits).
// The product q d2 in that definition is then generalised to an unknown M (no multiplier for the
// SAT solver), and the one property of the product the proof needs is given back as two facts,
// monotonicity for the constants c the range needs:  d2 > 0 and M = q d2  =>  (M > c d2 => q > c)
// and (M < c d2 => q < c) (c = INT64_MIN for q - 1 when b == 0, and INT32_MIN - 1, INT32_MIN,
// INT32_MAX + 1, INT32_MAX + 2 for the range). Those are proved over the integers here
// (fx.div.monotonicity_lemma), so every fact assumed is true of the real product; what is proved
// for every M is proved for q d2.
#include "prove.hpp"

#include <antkit/kernel/fixed.hpp>
#include <climits>
#include <functional>
#include <optional>

using namespace antkit::proofs;
namespace kn = antkit::kernel;

int main() {
  Session s;
  Prover p(s);
  constexpr int F = 16;
  using S = Int<140, true>; // the claims' own arithmetic: nothing in it can wrap
  const I32 a = I32::var("a"), b = I32::var("b");

  // The lemma the generalisation relies on, over the integers.
  {
    z3::context& c = s.ctx();
    const z3::expr q = c.int_const("q"), d = c.int_const("d"), k = c.int_const("c");
    p.claim_over_integers(
        "fx.div.monotonicity_lemma",
        z3::implies(d > 0, z3::implies(q * d > k * d, q > k) && z3::implies(q * d < k * d, q < k)));
  }

  // The domain, stated from a and b alone: d = |b|, s a 2^F with s = sign(b); the rounded quotient
  // floor((2 s a 2^F + d) / 2d) is in [INT32_MIN, INT32_MAX].
  const S sa(a), sb(b);
  const S d = select(sb < S(0), S(0) - sb, sb);
  const S san = select(sb < S(0), S(0) - sa, sa) * (S(1) << F); // s a 2^F
  const S t = S(2) * san + d, d2 = S(2) * d;
  const Bool in_range = S(INT32_MIN) * d2 <= t && t < (S(INT32_MAX) + S(1)) * d2;
  const Bool one_past = S(INT32_MIN) * d2 <= t && t < (S(INT32_MAX) + S(2)) * d2;
  s.clear_obligations(); // the spec's (140 bits: nothing wraps)

  // Runs the kernel, generalises the quotient's product, returns the result and the facts' q, M.
  struct Run {
    I32 raw;
    std::vector<z3::expr> products; // M, one per abstracted division
    std::vector<z3::expr> divisors; // the divisor d2 of that division, as the 128-bit fact has it
  };
  const auto run = [&]() {
    const I32 raw = kn::fx_div_raw<I32, I64, F>(a, b);
    Run out{raw, {}, {}};
    // Generalise every product in the facts (one per abstracted division; the quotient and the
    // remainder of one division share theirs).
    for (std::size_t i = 0; i < s.facts().size(); ++i) {
      if (auto prod = first_product(s.facts()[i])) {
        const z3::expr M = s.ctx().bv_const(s.fresh("M").c_str(), prod->get_sort().bv_size());
        // The multiplier's operands: sext(q) and sext(d2).
        const z3::expr q = prod->arg(0), dd = prod->arg(1);
        s.substitute(*prod, M);
        const unsigned w = prod->get_sort().bv_size();
        const z3::expr pos = z3::sgt(dd, s.ctx().bv_val(0, w));
        for (std::int64_t cst : {INT64_MIN, std::int64_t{INT32_MIN} - 1, std::int64_t{INT32_MIN},
                                 std::int64_t{INT32_MAX} + 1, std::int64_t{INT32_MAX} + 2}) {
          const z3::expr c = s.ctx().bv_val(cst, w);
          s.fact(
              z3::implies(pos, z3::implies(M > c * dd, q > c) && z3::implies(M < c * dd, q < c)));
        }
        out.products.push_back(M);
        out.divisors.push_back(dd);
      }
    }
    return out;
  };

  // One run of the kernel; its obligations are checked under the domain and, as a negative check,
  // shown to fail one quotient past the range.
  const Run r = run();
  const std::vector<Session::Obligation> obligations = s.obligations();
  p.assume(b != I32(0));
  p.assume(one_past);
  p.refute("fx.div: a quotient one past max() is caught by the narrowing", p.take_obligations());
  p.reset_domain();
  for (const auto& ob : obligations) s.oblige(ob.what, ob.holds);
  p.assume(b != I32(0));
  p.assume(in_range);
  p.no_undefined_behaviour("fx.div.defined_in_domain");
  if (r.products.size() != 1) {
    std::cout << "FAILED   expected one abstracted division, found " << r.products.size() << "\n";
    return 1;
  }
  // The division's quotient k and remainder r, M (= k d2 by the definition of division) and the
  // code's divisor d2 (the multiplier's second operand, sign-extended to 128 bits).
  const auto& division = s.signed_divisions().begin()->second;
  const I64 k(division.first), rem(division.second);
  const S M{Int<128, true>(r.products[0])};
  const S dcode{Int<128, true>(r.divisors[0])};
  const S corr = select(rem < I64(0), S(1), S(0));
  // raw = k - corr, hence raw d2 = M - corr d2 =: RD; the claims bound RD.
  const S RD = M - corr * dcode;
  const S err = RD - S(2) * san; // (raw - a 2^F / b) * 2d
  s.clear_obligations();
  p.claim("fx.div.code_divides_by_2|b|", dcode == d2);
  p.claim("fx.div.result_is_corrected_quotient", S(r.raw) == S(k) - corr);
  p.claim("fx.div.rounds_half_up (floor(a 2^F / b + 1/2))", RD <= t && t < RD + d2);
  p.claim("fx.div.error (-1/2 ulp < raw - a 2^F / b <= 1/2 ulp)", S(0) - d < err && err <= d);
  p.refute("fx.div: ties rounded down is false", RD < t && t <= RD + d2);
  p.refute("fx.div: error <= 1/4 ulp is false", S(0) - d <= S(2) * err && S(2) * err <= d);

  // b == 0 (outside the domain): saturates, and nothing is undefined except the require itself.
  p.reset_domain();
  p.assume(b == I32(0));
  s.clear_obligations();
  const I32 z = kn::fx_div_raw<I32, I64, F>(a, b);
  std::vector<Session::Obligation> kept;
  for (const auto& ob : s.obligations())
    if (ob.what.rfind("require: fixed-point division by zero", 0) != 0) kept.push_back(ob);
  s.clear_obligations();
  for (const auto& ob : kept) s.oblige(ob.what, ob.holds);
  p.claim("fx.div.by_zero_saturates (max() for a >= 0, min() for a < 0; no other UB)",
          z == select(a < I32(0), I32(INT32_MIN), I32(INT32_MAX)));
  return p.result();
}
