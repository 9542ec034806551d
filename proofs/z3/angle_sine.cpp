// Z3 proof: the shipped sine and cosine (angle.hpp sin_raw / cos_raw, the instantiations behind
// antkit::kernel::sin and cos) compute exactly the documented integer formula from the table
// entries, with no undefined behaviour, for every one of the 2^32 angles.
//
// The instantiations proved are the ones the kernel ships and tests use (sin<FixedT> instantiates
// sin_raw<Rep, wide_t<Rep>, F, std::uint32_t>):
//   Fx   = Fixed<int32, 16>   sin_raw<I32, I64, 16, U32>   (every caller in the code base)
//   F64  = Fixed<int64, 32>   sin_raw<I64, I128, 32, U32>   (tests; --f64-sine, --f64-cosine)
// ctest runs the Fx proof as proof.z3.angle_sine (no argument) and the F64 ones as
// proof.z3.angle_sine.f64.sine and .f64.cosine (one Session each); `--f64` runs all three.
// For each, over every angle a (a U32 unknown; there is no domain to assume):
//   sine.<fmt>.no_undefined_behaviour  every signed operation, shift, narrowing and both table
//                                      reads (index in [0, 1026)) of the template are defined;
//   sine.<fmt>.formula_is_exact        the specification below, evaluated in W, never wraps (so
//                                      each of its W-bit values is the integer it names);
//   sine.<fmt>.formula                 the result equals that specification:
//       quadrant q = a >> 30, offset o = a mod 2^30,
//       u = 2^30 - o if q is odd (quadrants 1 and 3 read the quarter-wave backwards) else o,
//       i = u >> 20, w = u mod 2^20, lo = kSineQ30[i], hi = kSineQ30[i + 1],
//       exact = lo * 2^20 + (hi - lo) * w                   (units of 2^-50, no rounding),
//       m = floor((exact + 2^(s-1)) / 2^s), s = 50 - F     (round half up to F bits),
//       result = -m if q >= 2 else m                        (the sign after rounding);
//   sine.<fmt>.magnitude_at_most_one   -2^F <= result <= 2^F;
//   cosine.<fmt>.is_shifted_sine       cos_raw(a) is the same formula at a + 2^30 (mod 2^32).
// The table is read through z3_int.hpp's lookup overload: one Z3 array constrained by 1026 facts
// (the shipped entries). Two lemmas about the entries are proved first, over every index:
//   sine.table.monotone                for every i in [0, 1023]: kSineQ30[i] <= kSineQ30[i+1]
//   sine.table.bounded                 for every i in [0, 1025]: 0 <= kSineQ30[i] <= 2^30 (>= 0:
//                                      the reads are unsigned words, the entries' conversion)
// and then stated as facts about the two reads at the code's index (instances of what was just
// proved, hence sound). With one lemma over the reals,
//   interpolation.in_range             0 <= lo, lo <= hi <= 2^30 (or w = 0), 0 <= w <= 2^20
//                                      imply 0 <= lo * 2^20 + (hi - lo) * w <= 2^50 (over the
//                                      reals, hence over the integers),
// that is all the magnitude bound needs (at i = 1024 the weight is 0; entry 1025 = sin(pi/2 + h)
// breaks monotonicity and is read only with w = 0). The lemma reaches the bit-vectors as a fact
// about the formula's W-bit terms, which is sound because formula_is_exact proved they do not
// wrap (this step, "a W-bit term that never wraps equals its integer", is the one link on paper).
//
// F64 proves the same claims, with the obligation lists split in two
// (no_undefined_behaviour_around): first every obligation that does not mention the product (hi -
// lo) * w -- among them the product's own, no signed overflow -- then, with one more lemma over the
// reals,
//   product.in_range                   |d| <= 2^32 and 0 <= w <= 2^20 imply |d w| <= 2^52,
// stated as a fact on the product's 128-bit term (sound because the first phase proved it does not
// wrap), the rest (the interpolant's sum and what follows it). Proved in one list, the sum's
// obligation asked the SAT solver to bound a 128-bit multiplier's output: 3 s in one run, past
// 10 minutes in another (which is why F64 used to be a manual run); split, each F64 part takes
// about 15 s of CPU.
//
// Together with tests/kernel/test_angle_sine_table.cpp, which checks exhaustively that every entry
// is sin(i h) correctly rounded to 2^-30 and that the exact interpolant lo*2^20 + (hi-lo)*w (in
// units of 2^-50) is within h^2/8 + 2^-31 of sin on the quarter wave, this gives the documented
// error bound |sin(a) - sin_exact(a)| <= 2^-(F+1) + 2.947e-7: the formula proved here is that
// interpolant, folded by the exact symmetries sin(pi - x) = sin x and sin(-x) = -sin x, rounded
// once half up (error <= 2^-(F+1)). The analytic step between the sampled points (the Lagrange
// remainder h^2/8) is on paper in that test's header; it is not machine-checked.
//
// Teeth (each must be refuted, i.e. Z3 must find a counterexample, or the test fails):
//   the formula with floor instead of round half up; |result| < 2^F (2^F is reached at a quarter
//   turn); the table monotone through its last entry; a read at i + 2 in range for every i <= 1024;
//   the interpolation lemma with a weight up to 2^20 + 1; (F64) the product lemma with a weight up
//   to 2^20 + 1.
#include "prove.hpp"

#include <antkit/kernel/angle.hpp>
#include <optional>
#include <string>
#include <vector>

using namespace antkit::proofs;
namespace kn = antkit::kernel;

namespace {

// The documented formula, computed in the code's wide type W from the angle's bits. Not under a
// Specification: its signed operations record obligations like the code's, and
// sine.<fmt>.formula_is_exact proves them, so each W-bit value below IS the integer it names (no
// wrap anywhere), which is what makes this the mathematical formula rather than a bit-vector one.
// (Stated in 128 bits for the 64-bit formats instead, the claim that the code equals it did not
// finish in 10 minutes: Z3 had to bit-blast a 128-bit multiplier against a 64-bit one.)
// round_half_up adds 2^(s-1) before the shift; the teeth pass false (floor).
template <class W>
struct SineSpec {
  W exact;
  W value;
  U32 index;
  U32 weight;
};
template <class W>
SineSpec<W> sine_formula(const U32& a, int F, bool round_half_up) {
  const U32 quadrant = a >> 30;
  const U32 offset = a & U32((1u << 30) - 1u);
  const U32 u = select((quadrant & U32(1)) != U32(0), U32(1u << 30) - offset, offset);
  const U32 i = u >> 20;
  const U32 w = u & U32((1u << 20) - 1u);
  const W lo(antkit::proofs::lookup(kn::angle_tables::kSineQ30, i));
  const W hi(antkit::proofs::lookup(kn::angle_tables::kSineQ30, i + U32(1)));
  const W exact = lo * W(1 << 20) + (hi - lo) * W(w);
  const int s = 50 - F;
  const W m = (exact + (round_half_up ? (W(1) << (s - 1)) : W(0))) >> s;
  return {exact, select((quadrant & U32(2)) != U32(0), -m, m), i, w};
}

// The two table lemmas (prove_table_lemmas, proved first in the same Session), instantiated at one
// index term (sound: instances of claims proved for every index; if those fail, the test fails).
void table_facts(Session& s, const U32& i) {
  const z3::expr t = table_array(kn::angle_tables::kSineQ30, 32);
  const z3::expr lo = z3::select(t, i.expr());
  const z3::expr hi = z3::select(t, (i + U32(1)).expr());
  const z3::expr top = s.ctx().bv_val(1u << 30, 32);
  s.fact(z3::implies(z3::ule(i.expr(), s.ctx().bv_val(1023, 32)), z3::ule(lo, hi)));
  s.fact(z3::implies(z3::ule(i.expr(), s.ctx().bv_val(1024, 32)),
                     z3::ule(lo, top) && z3::ule(hi, top)));
}

// The interpolation lemma (proved over the reals in main, interpolation.in_range), stated as a
// fact about one formula's W-bit terms. Sound because formula_is_exact proved that none of those
// W-bit operations wraps, so each term's bit-vector value is the integer the lemma speaks of.
// (Asked directly of the bit-vectors, "d * w <= d * 2^20 for w <= 2^20" did not finish in minutes:
// a SAT solver does not know that multiplication is monotone.)
template <class W>
void exact_range_fact(Session& s, const SineSpec<W>& spec) {
  const W lo(antkit::proofs::lookup(kn::angle_tables::kSineQ30, spec.index));
  const W hi(antkit::proofs::lookup(kn::angle_tables::kSineQ30, spec.index + U32(1)));
  const W w(spec.weight);
  s.clear_obligations(); // the reads' obligations are those of the formula, already proved
  const Bool premises = W(0) <= lo && lo <= W(1 << 30) && w <= W(1 << 20) &&
                        ((lo <= hi && hi <= W(1 << 30)) || w == W(0));
  const W top = W(1) << 50;
  s.fact(z3::implies(premises.expr(), (W(0) <= spec.exact && spec.exact <= top).expr()));
}

// The product lemma (proved over the reals in the F64 runs, product.in_range) as a fact on one
// interpolant's product term (hi - lo) w, the one multiplication of two unknowns in sin_raw and in
// the formula. Added only once the product's own obligation (no signed overflow) is proved, for
// every angle: then the product's W-bit value is the integer product the lemma speaks of.
void product_fact(Session& s, const z3::expr& product) {
  z3::context& c = s.ctx();
  const unsigned n = product.get_sort().bv_size();
  const z3::expr d = product.arg(0), w = product.arg(1);
  const auto pow2 = [&](int k) { return z3::shl(c.bv_val(1, n), c.bv_val(k, n)).simplify(); };
  s.fact(z3::implies(z3::sle(-pow2(32), d) && z3::sle(d, pow2(32)) && z3::sle(c.bv_val(0, n), w) &&
                         z3::sle(w, pow2(20)),
                     z3::sle(-pow2(52), product) && z3::sle(product, pow2(52))));
}

// The pending obligations in two phases (Q31.32): those that do not mention the product (hi - lo) w
// first -- among them the product's own, no signed overflow -- then, with product_fact, those that
// do (the interpolant's sum and what follows it). Without the fact the SAT solver must bound a
// 128-bit multiplier's output to prove the sum does not overflow: seconds in one run, past 10
// minutes in another.
bool no_undefined_behaviour_around(Session& s, Prover& p, const std::string& name,
                                   const z3::expr& term) {
  const std::optional<z3::expr> product = first_product(term);
  if (!product) {
    std::cout << "FAILED   " << name << ": no product (hi - lo) w in the interpolant\n";
    std::exit(1);
  }
  const std::vector<Session::Obligation> all = s.obligations();
  s.clear_obligations();
  std::vector<Session::Obligation> later;
  for (const auto& ob : all) {
    if (mentions_term(ob.holds, *product))
      later.push_back(ob);
    else
      s.oblige(ob.what, ob.holds);
  }
  if (!p.no_undefined_behaviour(name + " (not involving (hi - lo) w)")) return false;
  product_fact(s, *product);
  for (const auto& ob : later) s.oblige(ob.what, ob.holds);
  return p.no_undefined_behaviour(name + " (involving (hi - lo) w, with |(hi - lo) w| <= 2^52)");
}

// two_phase: the Q31.32 route (no_undefined_behaviour_around); Fx proves each list in one go.
template <class I, class W, int F>
void prove_format(Session& s, Prover& p, const std::string& fmt, const U32& a,
                  bool two_phase = false) {
  const I r = kn::sin_raw<I, W, F, U32>(a);
  if (two_phase)
    no_undefined_behaviour_around(s, p, "sine." + fmt + ".no_undefined_behaviour", r.expr());
  else
    p.no_undefined_behaviour("sine." + fmt + ".no_undefined_behaviour");
  const SineSpec<W> spec = sine_formula<W>(a, F, true);
  if (two_phase)
    no_undefined_behaviour_around(s, p, "sine." + fmt + ".formula_is_exact", spec.exact.expr());
  else
    p.no_undefined_behaviour("sine." + fmt + ".formula_is_exact (its W-bit operations never wrap)");
  // The table lemmas (proved in main before any format) at the code's index: the same Z3 term as
  // the code's, since the specification computes it with the same operations.
  table_facts(s, spec.index);
  p.claim("sine." + fmt + ".formula", W(r) == spec.value);
  exact_range_fact(s, spec);
  const I one = I(1) << F;
  p.claim("sine." + fmt + ".magnitude_at_most_one", -one <= r && r <= one);
  p.refute("sine." + fmt + ".teeth: the formula rounded down",
           W(r) == sine_formula<W>(a, F, false).value);
  p.take_obligations(); // the teeth's own formula: its obligations are the ones proved above
  p.refute("sine." + fmt + ".teeth: |result| < 2^F", -one < r && r < one);
}

// The cosine, in its own Session (so its claims do not carry the sine's facts).
template <class I, class W, int F>
void prove_cosine(Session& s, Prover& p, const std::string& fmt, const U32& a,
                  bool two_phase = false) {
  const I c = kn::cos_raw<I, W, F, U32>(a);
  if (two_phase)
    no_undefined_behaviour_around(s, p, "cosine." + fmt + ".no_undefined_behaviour", c.expr());
  else
    p.no_undefined_behaviour("cosine." + fmt + ".no_undefined_behaviour");
  const U32 shifted = a + U32(1u << 30);
  const SineSpec<W> cspec = sine_formula<W>(shifted, F, true);
  if (two_phase)
    no_undefined_behaviour_around(s, p, "cosine." + fmt + ".formula_is_exact", cspec.exact.expr());
  else
    p.no_undefined_behaviour("cosine." + fmt + ".formula_is_exact");
  table_facts(s, cspec.index);
  p.claim("cosine." + fmt + ".is_shifted_sine", W(c) == cspec.value);
}

} // namespace

// The table lemmas, over every index (Z3 splits the index over the array's 1026 facts).
void prove_table_lemmas(Prover& p) {
  const U32 i = U32::var("i");
  const U32 lo = antkit::proofs::lookup(kn::angle_tables::kSineQ30, i);
  const U32 hi = antkit::proofs::lookup(kn::angle_tables::kSineQ30, i + U32(1));
  p.assume(i <= U32(1023));
  p.claim("sine.table.monotone (i <= 1023: entry i <= entry i + 1)", lo <= hi);
  p.reset_domain();
  p.assume(i <= U32(1024));
  p.claim("sine.table.bounded (i <= 1025: 0 <= entry i <= 2^30)",
          lo <= U32(1u << 30) && hi <= U32(1u << 30));
  // Teeth: not monotone through the last entry (kSineQ30[1025] = sin(pi/2 + h) < 1 is there for
  // the read at u = 2^30, whose weight is 0), so the bound's case i = 1024 needs w = 0.
  p.refute("sine.table.teeth: monotone for i <= 1024", lo <= hi);
  // Teeth: one read past the table is out of range (the obligation every read records).
  const U32 past = antkit::proofs::lookup(kn::angle_tables::kSineQ30, i + U32(2));
  (void)past;
  p.refute("sine.table.teeth: index i + 2 is in range for every i <= 1024", p.take_obligations());
  p.reset_domain();
}

// |d| <= 2^32 and 0 <= w <= 2^20 imply |d w| <= 2^52 (over the reals, hence the integers): the
// bound product_fact states on the Q31.32 interpolants' products.
void prove_product_lemma(Session& s, Prover& p) {
  z3::context& c = s.ctx();
  const z3::expr d = c.real_const("d"), w = c.real_const("w");
  const z3::expr d_max = c.real_val(static_cast<std::int64_t>(1) << 32);
  const z3::expr w_max = c.real_val(1 << 20);
  const z3::expr p_max = c.real_val(static_cast<std::int64_t>(1) << 52);
  const z3::expr in_range = -p_max <= d * w && d * w <= p_max;
  p.claim_over_reals("product.in_range",
                     z3::implies(-d_max <= d && d <= d_max && 0 <= w && w <= w_max, in_range));
  p.refute_over_reals("product.teeth: weight up to 2^20 + 1",
                      z3::implies(-d_max <= d && d <= d_max && 0 <= w && w <= w_max + 1, in_range));
}

int main(int argc, char** argv) {
  const std::string part = argc > 1 ? argv[1] : "";
  if (part != "" && part != "--f64" && part != "--f64-sine" && part != "--f64-cosine") {
    std::cerr << "usage: proof_z3_angle_sine [--f64 | --f64-sine | --f64-cosine]\n";
    return 2;
  }
  const bool fx = part == "" || part == "--f64";
  int failed = 0;
  // Each part runs in its own Session: a claim is checked with every fact of its Session, and the
  // facts of one format only slow the others down (measured: 54 s CPU in one Session).
  {
    Session s;
    Prover p(s);
    // The interpolation lemma (nonlinear: d * w): for entries lo, hi in [0, 2^30] with lo <= hi,
    // or any entries at weight w = 0, and w in [0, 2^20],
    //     0 <= lo * 2^20 + (hi - lo) * w <= 2^50.
    // Proved over the reals (nlsat decides it; over the integers Z3's search took 7 s in one run
    // and did not finish in another): it then holds for the integers, a subset, in particular.
    z3::context& c = s.ctx();
    const z3::expr lo = c.real_const("lo"), hi = c.real_const("hi"), w = c.real_const("w");
    const z3::expr step = c.real_val(1 << 20);
    const z3::expr e = lo * step + (hi - lo) * w;
    const z3::expr top = c.real_val(static_cast<std::int64_t>(1) << 30);
    const z3::expr range = 0 <= e && e <= c.real_val(static_cast<std::int64_t>(1) << 50);
    const z3::expr premises =
        0 <= lo && lo <= top && 0 <= w && w <= step && ((lo <= hi && hi <= top) || w == 0);
    p.claim_over_reals("interpolation.in_range", z3::implies(premises, range));
    // Teeth: a weight one past 2^20 overshoots (lo = 0, hi = 2^30): the bound rests on w <= 2^20.
    const z3::expr loose = 0 <= lo && lo <= hi && hi <= top && w == step + 1;
    p.refute_over_reals("interpolation.teeth: weight up to 2^20 + 1", z3::implies(loose, range));
    failed |= p.result();
  }
  // Each format in its own Session, which first proves the table lemmas it then uses as facts.
  // (Tried: the table as an unconstrained array in the format Sessions, with the lemmas proved once
  // apart; the no-overflow checks got faster, but sine.Fx.formula, which
  // relates the code's reads to the specification's, did not finish in 8 minutes.)
  const auto run = [&failed](auto prove) {
    Session s;
    Prover p(s);
    prove_table_lemmas(p);
    prove(s, p, U32::var("a"));
    failed |= p.result();
  };
  if (fx) {
    run([](Session& s, Prover& p, const U32& a) { prove_format<I32, I64, 16>(s, p, "Fx", a); });
    run([](Session& s, Prover& p, const U32& a) { prove_cosine<I32, I64, 16>(s, p, "Fx", a); });
  }
  // F64 (used by tests, by no caller), one part per run: ctest runs `--f64-sine` and `--f64-cosine`
  // as the tests proof.z3.angle_sine.f64.sine and .f64.cosine (proofs/CMakeLists.txt); `--f64` runs
  // the Fx proof and both. Each proves the product lemma it relies on first.
  const auto run_f64 = [&run, &failed](auto prove) {
    {
      Session s;
      Prover p(s);
      prove_product_lemma(s, p);
      failed |= p.result();
    }
    run(prove);
  };
  const auto f64_sine = [](Session& s, Prover& p, const U32& a) {
    prove_format<I64, I128, 32>(s, p, "F64", a, true);
  };
  const auto f64_cosine = [](Session& s, Prover& p, const U32& a) {
    prove_cosine<I64, I128, 32>(s, p, "F64", a, true);
  };
  if (part == "--f64" || part == "--f64-sine") run_f64(f64_sine);
  if (part == "--f64" || part == "--f64-cosine") run_f64(f64_cosine);
  return failed;
}
