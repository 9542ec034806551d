// Z3 proof: Lemire's rejection in bounded_u32 (random.hpp) is exact, so Stream::below is unbiased.
//
// Instantiates the template copy proofs/z3/bounded_u32_template.hpp with Z3 bit-vectors (the copy
// is held to the shipped function by tests/proofs/test_bounded_u32_copy.cpp; see PROOFS.md).
//
// For every n in [1, 2^32) and every word x (the documented domain: n >= 1), with m = x * n,
// t = 2^32 mod n and q = floor(2^32 / n):
//   lemire.no_undefined_behaviour       the template's operations are defined (% and / by n != 0)
//   lemire.threshold_is_euclid          the code's threshold t and q satisfy q * n + t = 2^32, t <
//   n lemire.accepts_iff_low_ge_t         accepted  <=>  (m mod 2^32) >= t
//   lemire.output_is_high_word          out = m div 2^32
//   lemire.preimage_is_a_product_range  for every v < n: accepted and out == v  <=>
//                                       m in [v * 2^32 + t, (v + 1) * 2^32), a range of length q *
//                                       n
// So each v < n is produced by the words x whose multiple x * n falls in one range of length q * n:
// exactly q of them (Coq: Lemire.v, multiples_in_range), the same q for every v, and every accepted
// output is below n (Lemire.v, output_below_n); given acceptance, each value has probability 1 / n.
// The arithmetic that needs no bit-vectors (uniqueness of Euclid's quotient and remainder, and how
// many multiples of n a range holds) is proved over the integers in proofs/coq/Lemire.v.
#include "bounded_u32_template.hpp"
#include "prove.hpp"

using namespace antkit::proofs;

namespace {

struct Z3Words {
  using u32 = U32;
  using u64 = U64;
  using boolean = Bool;
  static U32 select(const Bool& c, const U32& a, const U32& b) {
    return antkit::proofs::select(c, a, b);
  }
  static Bool select(const Bool& c, const Bool& a, const Bool& b) {
    return antkit::proofs::select(c, a, b);
  }
};

} // namespace

int main() {
  Session s;
  Prover p(s);
  const U32 x = U32::var("x");
  const U32 n = U32::var("n");
  p.assume(n >= 1u);

  const auto [accepted_x, out_x] = bounded_u32_t<Z3Words>(x, n);
  p.no_undefined_behaviour("lemire.no_undefined_behaviour");

  // Generalise the product: every claim below is proved for ANY 64-bit word M in place of
  // x * n (a bit-vector multiplier is what SAT solvers find hardest, and none of these facts needs
  // more of the product than the domain facts stated with it). Proved for all M, so for M = x * n.
  const U64 n64 = U64(n), x64 = U64(x);
  const U64 M = U64::var("M");
  const z3::expr product = (x64 * n64).expr();
  z3::expr_vector from(s.ctx()), to(s.ctx());
  from.push_back(product);
  to.push_back(M.expr());
  const Bool accepted(z3::expr(accepted_x.expr()).substitute(from, to));
  const U32 out(z3::expr(out_x.expr()).substitute(from, to));
  s.clear_obligations(); // the ones above were checked; the spec below has its own

  // t and q: the remainder and quotient of 2^32 by n, from the code's own 32-bit remainder and
  // quotient k of 2^32 - n. lemire.threshold_is_euclid shows q * n + t = 2^32 with t < n, and that
  // equation has one solution (Coq: proofs/coq/Lemire.v, euclid_unique), so t = 2^32 mod n and
  // q = floor(2^32 / n).
  const U32 minus_n = U32(0) - n;
  const U32 k = minus_n / n;
  const U64 t = U64(minus_n % n);
  const U64 two32 = U64(1) << 32;
  const U64 low = M & U64(0xFFFFFFFFu);
  const U64 high = M >> 32;

  // q * n = (k + 1) * n, written k * n + n so that the product term is the one Euclid's fact names.
  p.claim("lemire.threshold_is_euclid", U64(k) * n64 + n64 + t == two32 && t < n64);
  p.claim("lemire.accepts_iff_low_ge_t", accepted == (low >= t));
  p.claim("lemire.output_is_high_word", U64(out) == high);

  // For v < n: the words with accepted output v are exactly those whose product lies in
  // [v * 2^32 + t, (v + 1) * 2^32), a half-open range of length 2^32 - t = q * n. How many words x
  // have x * n in such a range is then arithmetic (Coq: Lemire.v, multiples_in_range): exactly
  // q = floor(2^32 / n), the same for every v.
  const U32 v = U32::var("v");
  const U64 v64 = U64(v);
  const U64 first = (v64 << 32) + t;
  const U64 past = (v64 + U64(1)) << 32;
  p.claim("lemire.preimage_is_a_product_range",
          z3::implies((v < n).expr(),
                      ((accepted && U64(out) == v64) == (first <= M && M < past)).expr()));
  return p.result();
}
