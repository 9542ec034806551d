// Z3 proof: the shipped fixed-point multiply for Q31.32, fx_mul_raw<I64, I128, 32> (fixed.hpp; what
// Fixed<std::int64_t, 32>::operator* instantiates with std::int64_t / __int128), instantiated with
// Z3 bit-vectors: the same claims that fixed_ops.cpp proves for Q15.16.
//
//   q31.mul.no_overflow      the 128-bit product of any two sign-extended 64-bit values fits.
//   q31.mul.defined_in_domain   every operation is defined when the rounded result is in range; a
//                            result one past max() is caught by the narrowing.
//   q31.mul.rounds_half_up   raw = floor((a b + 2^31) / 2^32): -2^31 < raw 2^32 - a b <= 2^31, i.e.
//                            error <= 1/2 ulp, ties toward +infinity; and raw IS that floor.
//   teeth                    error <= 1/4 ulp and ties rounded down are refuted; an N-bit product
//                            in N bits overflows.
//
// How the 128-bit multiplier is kept away from the rounding claims: after q31.mul.no_overflow is
// proved on the real product, the product term is replaced in the code's result by an unknown P
// constrained only by the products' range |P| <= 2^126 (true of every product of two int64, whose
// magnitude is at most 2^63 * 2^63). What is proved for every such P holds for P = a b. The
// rounding is then linear: an addition, a shift and a narrowing.
#include "prove.hpp"

#include <antkit/kernel/fixed.hpp>
#include <chrono>

using namespace antkit::proofs;
namespace kn = antkit::kernel;

int main() {
  Session s;
  Prover p(s);
  constexpr int F = 32;
  using S = Int<140, true>; // the claims' own arithmetic: nothing in it can wrap
  const I64 a = I64::var("a"), b = I64::var("b");

  // The real product first: its only obligation is "signed *" on the 128-bit product.
  const auto t0 = std::chrono::steady_clock::now();
  const I64 raw = kn::fx_mul_raw<I64, I128, F>(a, b);
  const z3::expr product = (I128(a) * I128(b)).expr(); // the same term the kernel built
  {
    z3::expr mul_ok = s.ctx().bool_val(true);
    for (const auto& ob : s.obligations())
      if (ob.what == "signed *") mul_ok = mul_ok && ob.holds;
    s.clear_obligations(); // the rest are checked below, on the generalised product
    p.claim("q31.mul.no_overflow (the 128-bit product of any two int64)", mul_ok);
  }
  {
    const I64 m = a * b;
    (void)m;
    p.refute("q31.mul.no_overflow is not trivial (a 64-bit product in 64 bits)",
             p.take_obligations());
  }

  // Generalise the product.
  const I128 P = I128::var("P");
  s.substitute(product, P.expr());
  z3::expr_vector from(s.ctx()), to(s.ctx());
  from.push_back(product);
  to.push_back(P.expr());
  const I64 r(z3::expr(raw.expr()).substitute(from, to));

  const S sP(P), sr(r), h = S(1) << (F - 1);
  const S bound = S(1) << 126;
  const S rounded = (sP + h) >> F;
  const Bool in_products = S(0) - bound <= sP && sP <= bound;
  const Bool in_range = S(INT64_MIN) <= rounded && rounded <= S(INT64_MAX);
  const Bool one_past = S(INT64_MIN) <= rounded && rounded <= S(INT64_MAX) + S(1);
  const S err = (sr << F) - sP; // raw 2^F - a b
  s.clear_obligations();        // the claims' own (140 bits: nothing wraps)
  // Re-run the kernel so that its obligations are the pending ones (same terms; P substituted).
  {
    const I64 again = kn::fx_mul_raw<I64, I128, F>(a, b);
    (void)again;
    s.substitute(product, P.expr());
    std::vector<Session::Obligation> obs;
    for (const auto& ob : s.obligations())
      if (ob.what != "signed *") obs.push_back(ob); // the product's: q31.mul.no_overflow
    s.clear_obligations();
    p.assume(in_products);
    p.assume(one_past);
    z3::expr all = s.ctx().bool_val(true);
    for (const auto& ob : obs) all = all && ob.holds;
    p.refute("q31.mul: a result one past max() is caught by the narrowing", all);
    p.reset_domain();
    p.assume(in_products);
    p.assume(in_range);
    for (const auto& ob : obs) s.oblige(ob.what, ob.holds);
  }
  p.no_undefined_behaviour("q31.mul.defined_in_domain");
  p.claim("q31.mul.rounds_half_up (-1/2 ulp < error <= 1/2 ulp)", S(0) - h < err && err <= h);
  p.claim("q31.mul.is_floor_formula (raw = floor((a b + 2^31) / 2^32))", sr == rounded);
  p.refute("q31.mul: error <= 1/4 ulp is false", S(0) - (h >> 1) <= err && err <= (h >> 1));
  p.refute("q31.mul: ties rounded down is false", S(0) - h <= err && err < h);
  const auto ms =
      std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - t0)
          .count();
  std::cout << "q31.mul: " << ms << " ms in all\n";
  return p.result();
}
