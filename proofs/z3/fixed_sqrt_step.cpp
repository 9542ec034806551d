// Z3 proof: the loop invariant of the shipped digit-by-digit square root (fixed.hpp: isqrt_start,
// isqrt_step, which isqrt_floor runs Top/2 + 1 times), for the two instantiations that ship:
// isqrt_floor<int64, 46> (sqrt of Q15.16, Fx) and isqrt_floor<int128, 94> (sqrt of Q31.32).
//
// The invariant, with bit = 4^k before an iteration, S = 4^(k+1) the scale, y the root digits
// decided so far and Q a ghost for y^2:
//
//   Inv(r, rem, S, y, Q):  r = y S,  rem = n - Q S,  0 <= rem < 2 r + S,  0 <= y <= Q
//
// Claims:
//   sqrt.loop.start          (bit-vectors, the code) isqrt_start<W, Top>(n) for 0 <= n < 4 * 2^Top:
//                            r = 0, rem = n (Inv with S = 4^(Top/2 + 1), y = Q = 0), bit =
//                            4^(Top/2).
//   sqrt.step.code           (bit-vectors, the code) for every state with 1 <= bit <= 2^Top and
//                            0 <= r, rem < 4 * 2^Top, isqrt_step is defined and computes exactly
//                            (as integers) r' = floor(r/2) + bit or floor(r/2), rem' = rem - r -
//                            bit or rem (by d = [rem >= r + bit]), bit' = floor(bit / 4).
//   sqrt.step[k=..]          (integers, one claim per k = Top/2 .. 0) those formulas keep Inv:
//                            Inv(.., S = 4^(k+1), y, Q) => Inv(.., S = 4^k, 2y + d, 4Q + 4yd + d),
//                            and Inv implies the ranges sqrt.step.code assumes.
//   sqrt.ghost.square        (integers) Q = y^2, d in {0, 1} => 4Q + 4yd + d = (2y + d)^2, so Q
//                            stays y^2 along the loop (it starts as 0 = 0^2).
//   sqrt.loop.end            (integers) Inv with S = 1 and Q = y^2: r^2 <= n < (r+1)^2, rest = n -
//                            r^2 <= 2r.
//
// The composition (on paper, each link machine-checked above): isqrt_floor runs isqrt_start, then
// isqrt_step for i = 0 .. Top/2, i.e. with bit = 4^k for k = Top/2 .. 0 (start sets 4^(Top/2), each
// step sets floor(bit / 4)), so by induction Inv holds with S = 4^(k+1) before the iteration of k
// and with S = 1 after the last one; sqrt.loop.end then gives the floor root and the rest that
// fx_sqrt_raw rounds (proofs/z3/fixed_sqrt.cpp proves that rounding over the code's own
// expression). tests/kernel/test_fixed.cpp checks the same invariant along whole runs (a property).
//
// Why this shape. Stated directly over the 24 unrolled iterations, Z3 did not finish in 10 minutes.
// One iteration over bit-vectors with a symbolic k (shifts by 2k + 2 on both sides of r' = y' 4^k)
// had not finished after three minutes; with k a constant, one bit-vector claim per k took 0.3 s at
// k = 23 but 30-47 s at k <= 3 (6 minutes for Q15.16 alone). Splitting the step into what the code
// computes (bit-vectors, no ghost, one claim for every k) and why it keeps Inv (linear integer
// arithmetic with the constant S: milliseconds per k) takes seconds for both formats. The ghost Q
// keeps the integer claims linear; the one product, (2y + d)^2, is sqrt.ghost.square.
//
// Teeth (each must get a counterexample, else the test fails): n = 4 * 2^Top (one past the domain)
// breaks the start; the code does not take the digit only when rem > r + bit; at every k, the rule
// "take when rem > r + bit" breaks Inv and the tighter bound rem < r + S is not kept.
#include "prove.hpp"

#include <antkit/kernel/fixed.hpp>
#include <string>

using namespace antkit::proofs;
namespace kn = antkit::kernel;

namespace {

// A negative check over the integers: `c` must NOT hold under `given`; prints the counterexample.
// (Prover::refute uses the QF_BV solver; this helper belongs beside it in prove.hpp.)
int refute_over_integers(Session& s, const std::string& name, const z3::expr& given,
                         const z3::expr& c) {
  z3::solver solver(s.ctx());
  solver.add(given);
  solver.add(!c);
  if (solver.check() == z3::sat) {
    std::cout << "refuted  " << name << " (as it must be), e.g.";
    const z3::model m = solver.get_model();
    for (unsigned i = 0; i < m.size(); ++i)
      if (m[i].arity() == 0)
        std::cout << " " << m[i].name().str() << "=" << m.get_const_interp(m[i]);
    std::cout << std::endl;
    return 0;
  }
  std::cout << "NO TEETH " << name << ": expected a counterexample\n";
  return 1;
}

z3::expr pow2(z3::context& c, int k) {
  std::string digits = "1";
  for (int i = 0; i < k; ++i) { // decimal doubling: 2^k for k up to a few hundred
    int carry = 0;
    for (auto it = digits.rbegin(); it != digits.rend(); ++it) {
      const int v = (*it - '0') * 2 + carry;
      *it = static_cast<char>('0' + v % 10);
      carry = v / 10;
    }
    if (carry != 0) digits.insert(digits.begin(), static_cast<char>('0' + carry));
  }
  return c.int_val(digits.c_str());
}

// The invariant over the integers, with scale S = 4^(k+1).
z3::expr inv(const z3::expr& n, const z3::expr& r, const z3::expr& rem, const z3::expr& S,
             const z3::expr& y, const z3::expr& Q) {
  return r == y * S && rem == n - Q * S && 0 <= rem && rem < 2 * r + S && 0 <= y && y <= Q;
}

// Part 1, bit-vectors: the code of one iteration is defined and computes the integer formulas
//   r' = floor(r / 2) + d bit or floor(r / 2),  rem' = rem - (r + bit) or rem,  bit' = floor(bit /
//   4)
// with d = [rem >= r + bit], for every state in the ranges that part 2 shows Inv implies.
template <class W, int Top, class G>
void step_code(Prover& p, const std::string& fmt) {
  const W r = W::var(fmt + ".r"), rem = W::var(fmt + ".rem"), bit = W::var(fmt + ".bit");
  const G bound = G(1) << (Top + 2);
  {
    Session::Specification spec;
    p.assume(G(1) <= G(bit) && G(bit) <= (G(1) << Top) && G(0) <= G(r) && G(r) < bound &&
             G(0) <= G(rem) && G(rem) < bound);
  }
  kn::IsqrtState<W> st{r, rem, bit};
  kn::isqrt_step(st);
  Bool formulas(true), wrong(true);
  {
    Session::Specification spec;
    const Bool d = G(rem) >= G(r) + G(bit);
    const G half = G(r) >> 1; // arithmetic shift: floor(r / 2)
    formulas = G(st.r) == select(d, half + G(bit), half) &&
               G(st.remaining) == select(d, G(rem) - G(r) - G(bit), G(rem)) &&
               G(st.bit) == (G(bit) >> 2);
    wrong = G(st.remaining) == select(G(rem) > G(r) + G(bit), G(rem) - G(r) - G(bit), G(rem));
  }
  p.claim(fmt + ".sqrt.step.code (defined; computes the integer formulas exactly)", formulas);
  p.refute(fmt + ".sqrt.step.code: the code does not take the digit only when rem > r + bit",
           wrong);
  p.reset_domain();
}

// Part 2, integers: the formulas keep Inv, for each k = Top/2 .. 0 (one linear claim per k: with
// k a constant, y S and Q S are linear; with k symbolic they are products of unknowns, and over
// bit-vectors the same step, stated with symbolic shifts, had not finished after three minutes).
// Also: Inv implies the ranges part 1 assumes. Teeth at every k: the digit rule "rem > r + bit"
// and the tighter bound rem < r + S are not invariant.
int step_math(Prover& p, Session& s, const std::string& fmt, int Top) {
  z3::context& c = s.ctx();
  const z3::expr n = c.int_const((fmt + ".n").c_str()), r = c.int_const((fmt + ".r").c_str()),
                 rem = c.int_const((fmt + ".rem").c_str()), y = c.int_const((fmt + ".y").c_str()),
                 Q = c.int_const((fmt + ".Q").c_str());
  const z3::expr bound = pow2(c, Top + 2);
  int no_teeth = 0;
  for (int k = Top / 2; k >= 0; --k) {
    const std::string at = fmt + ".sqrt.step[k=" + std::to_string(k) + "]";
    const z3::expr bit = pow2(c, 2 * k), S = pow2(c, 2 * k + 2);
    const z3::expr pre = 0 <= n && n < bound && inv(n, r, rem, S, y, Q);
    // The formulas of part 1 (integer / is floor division here: its divisor is positive).
    const auto r2 = [&](const z3::expr& d) { return z3::ite(d, r / 2 + bit, r / 2); };
    const auto rem2 = [&](const z3::expr& d) { return z3::ite(d, rem - r - bit, rem); };
    const auto post = [&](const z3::expr& d) {
      const z3::expr y2 = 2 * y + z3::ite(d, c.int_val(1), c.int_val(0));
      const z3::expr Q2 = 4 * Q + z3::ite(d, 4 * y + 1, c.int_val(0));
      return inv(n, r2(d), rem2(d), bit, y2, Q2);
    };
    p.claim_over_integers(
        at + " (Inv kept: e = 2k, y' = 2y + d, Q' = 4Q + 4yd + d; part 1's ranges hold)",
        z3::implies(pre, post(rem >= r + bit) && 1 <= bit && bit <= pow2(c, Top) && 0 <= r &&
                             r < bound && 0 <= rem && rem < bound));
    no_teeth += refute_over_integers(s, at + ": the rule take when rem > r + bit breaks Inv", pre,
                                     post(rem > r + bit));
    no_teeth +=
        refute_over_integers(s, at + ": rem < r + S is not an invariant", pre && rem < r + S,
                             rem2(rem >= r + bit) < r2(rem >= r + bit) + bit);
  }
  return no_teeth;
}

// The start and the end, over bit-vectors and integers.
template <class W, int Top, class G>
void start(Prover& p, const std::string& fmt) {
  const W n = W::var(fmt + ".n");
  const G gn(n), one(1);
  const G n_bound = one << (Top + 2);
  const auto inv0 = [&](const kn::IsqrtState<W>& st) {
    Session::Specification spec; // y = Q = 0, S = 4^(Top/2 + 1)
    const G gr(st.r), grem(st.remaining);
    return gr == G(0) && grem == gn && G(0) <= grem && grem < G(2) * gr + n_bound;
  };
  p.assume(G(0) <= gn && gn < n_bound);
  const kn::IsqrtState<W> st = kn::isqrt_start<W, Top>(n);
  p.claim(fmt + ".sqrt.loop.start (Inv with e = Top + 2, y = Q = 0; bit = 4^(Top/2))",
          inv0(st) && G(st.bit) == (one << Top));
  p.reset_domain();
  p.assume(G(0) <= gn && gn <= n_bound);
  p.refute(fmt + ".sqrt.loop.start: n = 4 * 2^Top (one past the domain) breaks Inv", inv0(st));
  p.reset_domain();
}

void end_and_ghost(Prover& p, Session& s) {
  z3::context& c = s.ctx();
  const z3::expr y = c.int_const("y"), Q = c.int_const("Q"), d = c.int_const("d");
  const z3::expr n = c.int_const("n"), r = c.int_const("r"), rem = c.int_const("rem");
  p.claim_over_integers("sqrt.ghost.square (Q = y^2, d in {0,1} => 4Q + 4yd + d = (2y + d)^2)",
                        z3::implies(Q == y * y && (d == 0 || d == 1),
                                    4 * Q + 4 * y * d + d == (2 * y + d) * (2 * y + d)));
  p.claim_over_integers(
      "sqrt.loop.end (Inv with S = 1 and Q = y^2: r^2 <= n < (r+1)^2, rest = n - r^2 <= 2r)",
      z3::implies(inv(n, r, rem, c.int_val(1), y, Q) && Q == y * y,
                  r * r <= n && n < (r + 1) * (r + 1) && rem == n - r * r && rem <= 2 * r));
}

} // namespace

int main() {
  Session s;
  Prover p(s);
  end_and_ghost(p, s);
  start<I64, 46, I128>(p, "q15.16");
  start<I128, 94, Int<256, true>>(p, "q31.32");
  step_code<I64, 46, I128>(p, "q15.16");
  step_code<I128, 94, Int<256, true>>(p, "q31.32");
  int no_teeth = step_math(p, s, "q15.16", 46);
  no_teeth += step_math(p, s, "q31.32", 94);
  return p.result() == 0 && no_teeth == 0 ? 0 : 1;
}
