// Z3 proof: Lemire's rejection in the shipped bounded_u32 (random.hpp) is exact, so Stream::below
// is unbiased.
//
// A proof about shipped code: antkit::kernel::bounded_u32 is bounded_u32_t<MachineWords>, and this
// file instantiates the same template, bounded_u32_t, with Z3 bit-vector words. Its two `if`s fork
// the run (z3_int.hpp, Session::decide): low >= n (accept at once), low < n and low < t (reject),
// low < n and low >= t (accept); every claim is checked on every path under that path's condition.
//
// For every n in [1, 2^32) and every word x (the documented domain: n >= 1), with m = x * n,
// t = 2^32 mod n and q = floor(2^32 / n):
//   lemire.no_undefined_behaviour       the template's operations are defined (% by n != 0)
//   lemire.threshold_is_euclid          the code's threshold t and q satisfy q * n + t = 2^32,
//                                       t < n
//   lemire.accepts_iff_low_ge_t         accepted  <=>  (m mod 2^32) >= t
//   lemire.output_is_high_word          on acceptance out = m div 2^32; on rejection out is
//   untouched lemire.preimage_is_a_product_range  for every v < n: accepted and out == v  <=>
//                                       m in [v * 2^32 + t, (v + 1) * 2^32), a range of length q *
//                                       n
// So each v < n is produced by the words x whose multiple x * n falls in one range of length q * n:
// exactly q of them (Coq: Lemire.v, multiples_in_range), the same q for every v, and every accepted
// output is below n (Lemire.v, output_below_n); given acceptance, each value has probability 1 / n.
// The arithmetic that needs no bit-vectors (uniqueness of Euclid's quotient and remainder, and how
// many multiples of n a range holds) is proved over the integers in proofs/coq/Lemire.v.
//
// Teeth: lemire.teeth.* state claims that are wrong by one (a threshold one higher, an output one
// lower) and require Z3 to find a counterexample; if it did not, the claims above could be vacuous
// (an unsatisfiable domain or path condition), and the test fails.
#include "prove.hpp"

#include <antkit/kernel/random.hpp>

using namespace antkit::proofs;

namespace {

struct Z3Words {
  using u32 = U32;
  using u64 = U64;
};

} // namespace

int main() {
  Session s;
  Prover p(s);
  const U32 x = U32::var("x");
  const U32 n = U32::var("n");
  const Bool domain = n >= 1u;
  p.assume(domain);

  const U64 n64 = U64(n), x64 = U64(x);
  const U64 M = x64 * n64;
  // t and q: the remainder and quotient of 2^32 by n, from the code's own 32-bit remainder and
  // quotient k of 2^32 - n (the same Z3 terms as the code's, so the same abstracted division).
  // lemire.threshold_is_euclid shows q * n + t = 2^32 with t < n, and that equation has one
  // solution (Coq: proofs/coq/Lemire.v, euclid_unique), so t = 2^32 mod n and q = floor(2^32 / n).
  const U32 minus_n = U32(0) - n;
  const U64 t = U64(minus_n % n);
  const U32 k = minus_n / n;
  const U64 two32 = U64(1) << 32;
  const U64 low = M & U64(0xFFFFFFFFu);
  const U64 high = M >> 32;
  s.clear_obligations(); // the specification's own % and / (by n >= 1), not the code's

  // q * n = (k + 1) * n, written k * n + n so that the product term is the one Euclid's fact names.
  p.claim("lemire.threshold_is_euclid", U64(k) * n64 + n64 + t == two32 && t < n64);

  const U32 untouched = U32::var("out_before");
  const U32 v = U32::var("v");
  const U64 v64 = U64(v);
  const U64 first = (v64 << 32) + t;
  const U64 past = (v64 + U64(1)) << 32;
  const int paths = for_each_path(s, [&] {
    U32 out = untouched;
    const bool accepted = antkit::kernel::bounded_u32_t<Z3Words>(x, n, out);
    p.no_undefined_behaviour("lemire.no_undefined_behaviour");
    const std::string where = accepted ? " (an accepting path)" : " (the rejecting path)";
    p.claim("lemire.accepts_iff_low_ge_t" + where, Bool(accepted) == (low >= t));
    p.claim("lemire.output_is_high_word" + where, accepted ? U64(out) == high : out == untouched);
    const Bool produced = Bool(accepted) && U64(out) == v64;
    p.claim("lemire.preimage_is_a_product_range" + where,
            z3::implies((v < n).expr(), (produced == (first <= M && M < past)).expr()));
    if (accepted) {
      p.refute("lemire.teeth: output is the high word minus one" + where,
               U64(out) + U64(1) == high);
    } else {
      p.refute("lemire.teeth: rejects only below t - 1" + where, low + U64(1) < t);
    }
  });
  std::cout << paths << " paths through bounded_u32_t\n";
  return p.result();
}
