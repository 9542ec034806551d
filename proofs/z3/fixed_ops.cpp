// Z3 proof: the shipped fixed-point kernels of fixed.hpp, instantiated with Z3 bit-vector integers
// (Fixed<int32, 16> = Fx, Q15.16, the format that ships; the conversions also for Fixed<int64,
// 32>), have no undefined behaviour in their documented domains and round as fixed.hpp documents.
//
// These are proofs about the shipped code: fx_mul_raw<I32, I64, 16> is the template that
// Fx::operator* instantiates with std::int32_t / std::int64_t (int_ops.hpp, route 1: Int's own
// operators record C++'s undefined-behaviour conditions, ops::require and ops::narrow record the
// domain preconditions). Each claim is followed by negative checks (`refuted ...`) that a wrong
// bound -- 1/4 ulp instead of 1/2, ties rounded down instead of up, a domain one bit too large --
// has a counterexample, so the claims are not vacuous.
//
//   fx.mul.*        raw = floor((a b + 2^(F-1)) / 2^F): -2^(F-1) < raw 2^F - a b <= 2^(F-1), so the
//                   error is <= 1/2 ulp with ties toward +infinity; defined whenever the rounded
//                   result is in range.
//   fx.from_int     exact, defined for v in [-2^(N-1-F), 2^(N-1-F) - 1] and not one further.
//   fx.floor/ceil/round   floor(a/2^F), ceil(a/2^F), floor(a/2^F + 1/2) for every a, no overflow.
//   fx.cast.*       Q15.16 -> Q31.32 exact; Q31.32 -> Q15.16 rounded half up (error <= 1/2 ulp of
//                   Q15.16) whenever the rounded result is in range.
//
// The product a b is generalised to an unknown P in [-2^(2N-2), 2^(2N-2)] (a superset of the
// products' range) for the rounding claims: proved for every such P, so for P = a b; what is
// specific to the multiplication -- that it cannot overflow 2N bits -- is the obligation
// fx.mul.no_overflow, proved first on the real product.
#include "prove.hpp"

#include <antkit/kernel/fixed.hpp>

using namespace antkit::proofs;
namespace kn = antkit::kernel;

// fixed_cast to more fraction bits names the type twice as wide as the target (fx_rescale_raw):
// for Z3 integers that is the bit-vector of twice the width.
template <int N, bool S>
struct antkit::kernel::ops::wide_of<Int<N, S>> {
  using type = Int<2 * N, S>;
};

namespace {

// Spec arithmetic: wide enough that nothing the claims compute can wrap (checked per operation
// anyway: Int records an obligation for every signed operation, outside Specification scopes).
template <int N>
using Spec = Int<2 * N + 8, true>;

template <class T>
T pow2(int k) {
  return T(1) << k;
}

template <class I, class W, int F>
void multiply(Prover& p, Session& s, const std::string& fmt) {
  constexpr int N = I::bits;
  using S = Spec<N>;
  const I a = I::var(fmt + ".a"), b = I::var(fmt + ".b");
  const I raw = kn::fx_mul_raw<I, W, F>(a, b);
  // The product's own obligation ("signed *"), on the real product, before it is generalised.
  z3::expr product = (W(a) * W(b)).expr(); // records a copy of the same obligation: harmless
  {
    std::vector<std::string> kept;
    z3::expr mul_ok = s.ctx().bool_val(true);
    std::vector<Session::Obligation> rest;
    for (const auto& ob : s.obligations()) {
      if (ob.what == "signed *")
        mul_ok = mul_ok && ob.holds;
      else
        rest.push_back(ob);
    }
    s.clear_obligations();
    p.claim(fmt + ".mul.no_overflow (the 2N-bit product of any two N-bit values)", mul_ok);
    for (const auto& ob : rest) s.oblige(ob.what, ob.holds);
  }
  // The product's overflow predicate has teeth: N-bit products do not fit N bits.
  {
    const I m = a * b;
    (void)m;
    p.refute(fmt + ".mul.no_overflow is not trivial (an N-bit product in N bits)",
             p.take_obligations());
  }
  const W P = W::var(fmt + ".P");
  s.substitute(product, P.expr());
  z3::expr_vector from(s.ctx()), to(s.ctx());
  from.push_back(product);
  to.push_back(P.expr());
  const I r(z3::expr(raw.expr()).substitute(from, to));

  const S bound = pow2<S>(2 * N - 2);
  const S sP(P), sr(r), h = pow2<S>(F - 1), one = pow2<S>(F);
  // The domain: P is a product of two N-bit values, and the rounded result is in I's range.
  const S rounded = (sP + h) >> F;
  const Bool in_products = S(0) - bound <= sP && sP <= bound;
  const Bool in_range =
      S(kn::ops::min_value<I>()) <= rounded && rounded <= S(kn::ops::max_value<I>());
  s.clear_obligations(); // the spec's own (all defined: 2N + 8 bits)
  p.reset_domain();
  p.assume(in_products);
  // Teeth for the domain: one bit beyond the range the narrowing is caught.
  {
    p.assume(rounded <= S(kn::ops::max_value<I>()) + S(1) && S(kn::ops::min_value<I>()) <= rounded);
    const I r2 = kn::fx_mul_raw<I, W, F>(a, b);
    (void)r2;
    s.substitute(product, P.expr());
    z3::expr obs = p.take_obligations();
    p.refute(fmt + ".mul: a result one past max() is caught by the narrowing", obs);
    p.reset_domain();
    p.assume(in_products);
  }
  p.assume(in_range);
  const I r3 = kn::fx_mul_raw<I, W, F>(a, b);
  (void)r3;
  s.substitute(product, P.expr());
  p.no_undefined_behaviour(fmt + ".mul.defined_in_domain");
  const S err = (sr << F) - sP; // raw 2^F - a b
  s.clear_obligations();
  p.claim(fmt + ".mul.rounds_half_up (-1/2 ulp < error <= 1/2 ulp)", S(0) - h < err && err <= h);
  p.claim(fmt + ".mul.is_floor_formula", sr == rounded);
  p.refute(fmt + ".mul: error <= 1/4 ulp is false", S(0) - (h >> 1) <= err && err <= (h >> 1));
  p.refute(fmt + ".mul: ties rounded down is false", S(0) - h <= err && err < h);
  (void)one;
  p.reset_domain();
}

template <class I, class W, int F>
void conversions(Prover& p, Session& s, const std::string& fmt) {
  constexpr int N = I::bits;
  using S = Spec<N>;
  const I v = I::var(fmt + ".v");
  const S lo = S(0) - pow2<S>(N - 1 - F), hi = pow2<S>(N - 1 - F) - S(1);
  s.clear_obligations();
  // from_int: Fixed::from_int narrows an int32 to Rep, then fx_from_int_raw shifts.
  p.assume(lo <= S(v) && S(v) <= hi);
  const I r = kn::fx_from_int_raw<I, F>(v);
  p.claim(fmt + ".from_int exact in [-2^(N-1-F), 2^(N-1-F) - 1]", S(r) == S(v) * pow2<S>(F));
  p.reset_domain();
  p.assume(lo <= S(v) && S(v) <= hi + S(1));
  (void)kn::fx_from_int_raw<I, F>(v);
  p.refute(fmt + ".from_int: one past the domain overflows", p.take_obligations());
  p.reset_domain();

  // x * k (Fixed::operator*(Fixed, int32)) is ops::mul(raw, k) alone: defined exactly when the
  // product fits, which is C++'s rule itself; not restated here (a claim over the 2N-bit product
  // cost Z3 minutes for nothing the obligation does not already say).
  const I a = I::var(fmt + ".x");
  // floor, ceil, round: every a.
  const S sa(a), one = pow2<S>(F), h = pow2<S>(F - 1);
  s.clear_obligations();
  const I fl = kn::fx_floor_int<I, W, F>(a);
  p.claim(fmt + ".floor exact", S(fl) * one <= sa && sa < S(fl) * one + one);
  const I ce = kn::fx_ceil_int<I, W, F>(a);
  p.claim(fmt + ".ceil exact", S(ce) * one - one < sa && sa <= S(ce) * one);
  const I ro = kn::fx_round_int<I, W, F>(a);
  p.claim(fmt + ".round half up", S(ro) * one - h <= sa && sa < S(ro) * one + h);
  p.refute(fmt + ".round: half down is false", S(ro) * one - h < sa && sa <= S(ro) * one + h);
}

// fixed_cast between Q15.16 and Q31.32 (fx_rescale_raw, what fixed_cast instantiates).
void casts(Prover& p, Session& s) {
  using S = Int<140, true>;
  const I32 a = I32::var("cast.a");
  const I64 up = kn::fx_rescale_raw<I32, I64, 16, I64, 32>(a);
  p.claim("fx.cast.Q15.16_to_Q31.32 exact", S(up) == S(a) * (S(1) << 16));
  const I64 b = I64::var("cast.b");
  s.clear_obligations();
  const S sb(b), h = S(1) << 15;
  const S rounded = (sb + h) >> 16;
  const Bool in_range = S(INT32_MIN) <= rounded && rounded <= S(INT32_MAX);
  s.clear_obligations();
  p.assume(in_range);
  const I32 down = kn::fx_rescale_raw<I64, I128, 32, I32, 16>(b);
  const S err = (S(down) << 16) - sb;
  s.clear_obligations(); // the spec's
  // (The obligations of the kernel itself were recorded before the spec's; re-run to check them.)
  (void)kn::fx_rescale_raw<I64, I128, 32, I32, 16>(b);
  p.claim("fx.cast.Q31.32_to_Q15.16 rounds half up (-1/2 < error <= 1/2 ulp of Q15.16)",
          S(0) - h < err && err <= h);
  p.refute("fx.cast.Q31.32_to_Q15.16: error <= 1/4 ulp is false",
           S(0) - (h >> 1) <= err && err <= (h >> 1));
  p.reset_domain();
  p.assume(rounded <= S(INT32_MAX) + S(1) && S(INT32_MIN) <= rounded);
  (void)kn::fx_rescale_raw<I64, I128, 32, I32, 16>(b);
  p.refute("fx.cast.Q31.32_to_Q15.16: one past the range is caught by the narrowing",
           p.take_obligations());
  p.reset_domain();
}

} // namespace

int main() {
  Session s;
  Prover p(s);
  multiply<I32, I64, 16>(p, s, "fx");
  conversions<I32, I64, 16>(p, s, "fx");
  conversions<I64, I128, 32>(p, s, "fx64");
  casts(p, s);
  return p.result();
}
