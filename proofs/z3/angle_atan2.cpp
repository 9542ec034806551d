// Z3 proof: the shipped atan2 (angle.hpp atan2_raw, the instantiations behind
// antkit::kernel::atan2) is free of undefined behaviour for every input and computes exactly the
// documented integer formula from the table entries; its ratio is n/d rounded half up to 2^-30; the
// zero vector, the axes and the diagonals (hence the eight bearings) give their exact angles for
// every magnitude.
//
// The instantiations proved are the ones that ship (atan2(Fixed<Rep, F>, Fixed<Rep, F>)
// instantiates atan2_raw<Rep, wide_t<Rep>, uint32>; the int32 overload is the same as Fx's):
//   i32  atan2_raw<I32, I64, U32>    kernel::atan2(int32, int32) and atan2(Fx, Fx) (devices/)
//   q31  atan2_raw<I64, I128, U32>   atan2(Fixed<int64, 32>, ...) (tests/kernel/test_angle.cpp)
// `proof_z3_angle_atan2` proves i32 (ctest proof.z3.angle_atan2), `proof_z3_angle_atan2 q31` proves
// q31 (ctest proof.z3.angle_atan2.q31, proofs/CMakeLists.txt), `all` both; each format runs in its
// own Session, after the lemmas over the integers and the reals.
//
// For each format, over every pair (y, x) of I words (there is no domain to assume), with the fold
// ax = |x|, ay = |y| (in W), steep = ay > ax, n = min(ax, ay), d = max(ax, ay), D = d (1 if d = 0):
//   atan2.<fmt>.ratio_divides             the code divides t = 2^31 n + D by 2D (and n <= D);
//   atan2.<fmt>.ratio_is_the_quotient     its truncated quotient needs no floor correction
//                                         (remainder >= 0): ratio = that quotient;
//   atan2.<fmt>.ratio_rounds_half_up      ratio 2D <= 2^31 n + D < ratio 2D + 2D, i.e.
//                                         ratio = floor(2^30 n / D + 1/2) (n/d to 2^-30, ties up);
//   atan2.<fmt>.ratio_in_range            0 <= ratio <= 2^30;
//   atan2.<fmt>.ratio_exact_on_axes_and_diagonals   n = 0 gives 0, n = D gives 2^30;
//   atan2.<fmt>.no_undefined_behaviour    (three lists, see below) every signed operation (|x|, |y|
//                                         are negated in W, so -INT_MIN is defined), shift, the
//                                         division and remainder of div_round_half_up (divisor
//                                         2D >= 2, no INT_MIN / -1), the floor correction q - 1,
//                                         both narrowings to U32 (the ratio and the rounded
//                                         interpolant) and both table reads (index in [0, 1026));
//   atan2.<fmt>.index_at_most_1024, .entries_ordered (lo <= hi),
//   atan2.<fmt>.interpolant_between_entries   lo 2^20 <= exact <= hi 2^20 (steps of the above);
//   atan2.<fmt>.formula_is_exact          the specification below, evaluated in W, never wraps;
//   atan2.<fmt>.formula                   the result equals the documented formula:
//       i = ratio >> 20, w = ratio mod 2^20, lo = kAtanUnits[i], hi = kAtanUnits[i + 1],
//       exact = lo * 2^20 + (hi - lo) * w                           (units of 2^-20 unit),
//       base = floor((exact + 2^19) / 2^20)                          (round half up to a unit),
//       octant = 2^30 - base if steep else base,
//       angle = octant (x >= 0, y >= 0), 2^31 - octant (x < 0, y >= 0),
//               2^31 + octant (x < 0, y < 0), 2^32 - octant (x >= 0, y < 0),
//       result = 0 if x = y = 0, else angle mod 2^32;
//   atan2.<fmt>.base_between_entries      lo <= base <= hi and 0 <= base <= 2^29 (so the octant
//                                         angle is in [0, 2^29], or [2^29, 2^30] when steep);
//   atan2.<fmt>.origin                    atan2(0, 0) = 0;
//   atan2.<fmt>.axes                      (0, x > 0) -> 0, (y > 0, 0) -> 2^30, (0, x < 0) -> 2^31,
//                                         (y < 0, 0) -> 3 * 2^30, for every magnitude;
//   atan2.<fmt>.diagonals                 |x| = |y| != 0 -> 1, 3, 5, 7 times 2^29 by quadrant, for
//                                         every magnitude (INT_MIN included).
// The axes and diagonals cover the eight bearings (angle.hpp: kNeighbours8[k] is bearing k).
//
// How (and why each step is sound):
// - The table is read through z3_int.hpp's lookup overload (one Z3 array, 1026 entry facts). Three
//   lemmas are proved over every index first, then instantiated at the code's index as facts:
//     atan.table.monotone    for every i in [0, 1024]: kAtanUnits[i] <= kAtanUnits[i + 1]
//     atan.table.bounded     for every i in [0, 1024]: 0 <= kAtanUnits[i] <= 2^29 (entry 1025, read
//                            only at weight 0, is above: a tooth checks it)
//     atan.table.ends        kAtanUnits[0] = 0, kAtanUnits[1024] = 2^29 (atan 1 = 1/8 turn)
// - The division: z3_int.hpp abstracts t / 2D and t % 2D to unknowns q, r with C++'s definition
//   q 2D + r = t, |r| < 2D, r = 0 or r has t's sign (exact, in 2N bits). The product q 2D is then
//   generalised to an unknown M and given back as instances of
//     atan.division.monotonicity_lemma  d > 0 => (q d > c d => q > c) and (q d < c d => q < c)
//   (over the integers) for c = -1, 1, 2^30 - 1, 2^30 + 1, with c 2D written as shifts and an
//   addition: no multiplier for the SAT solver; what is proved for every such M holds for q 2D.
// - The code's terms are named by rebuilding them with the same shipped sub-templates
//   (div_round_half_up, interpolate_exact) and policy operations: Z3 shares identical terms, and
//   the rebuilt result is checked to be the code's result term (same Z3 id), the division to be the
//   code's (same dividend and divisor ids).
// - Some claims are kept as facts once proved (for every input, so true): ratio_divides,
//   ratio_is_the_quotient, ratio_in_range and ratio_exact_on_axes_and_diagonals, proved first
//   (everything after the division depends on the ratio's range), then index_at_most_1024,
//   entries_ordered and interpolant_between_entries.
// - The obligations are proved in three lists, each list's facts resting only on what the lists
//   before it proved: (1) "not involving (hi - lo) w": every obligation of the code that does not
//   mention the product (hi - lo) w -- among them the product's own, no signed overflow; (2)
//   "involving (hi - lo) w", with
//     atan.product.in_range  |d| <= 2^32 and 0 <= w <= 2^20 imply |d w| <= 2^52 (over the reals)
//   stated on the product's W-bit term (its value is the integer product: (1) proved it does not
//   wrap), the interpolant's sum; (3) "the rounding line", with
//     atan.interpolation.between_entries  lo <= hi and 0 <= w <= 2^20 imply
//                            lo 2^20 <= lo 2^20 + (hi - lo) w <= hi 2^20 (over the reals)
//   stated on the code's interpolant (whose operations (1) and (2) proved do not wrap), the
//   rounding line base = narrow((exact + 2^19) >> 20). The formula's own obligations
//   (formula_is_exact) are proved in the same two phases as (1) and (2). The step "a W-bit term
//   proved not to wrap equals its integer", which carries each lemma over the reals or integers to
//   the bit-vectors, is on paper (as in angle_sine.cpp).
//
// Not proved here: the error bound of at most 55 units (2^-32 turn) against the real atan2. That
// needs the entries to be atan(i/1024) 2^32/(2 pi) correctly rounded and the interpolation error
// h^2/8 max|atan''| (analysis of a transcendental function, outside what Z3 decides). What is
// proved reduces it to: the ratio's rounding (ratio_rounds_half_up: |ratio/2^30 - n/d| <= 2^-31,
// 0.32 unit through atan' <= 1), the result's rounding (formula: base rounds exact half up, 1/2
// unit), the exact folds (formula: atan(y/x) = 1/4 turn - atan(x/y) and the quadrant unfold are
// applied exactly, modulo a turn), and the table's accuracy with the interpolation error. The
// end-to-end bound is checked by sampling in tests/kernel/test_angle.cpp ("atan2 is within 55 units
// of the exact direction": random int32 vectors, small vectors, Q31.32 vectors); the atan table is
// not checked entry by entry against atan anywhere (tests/kernel/test_angle_sine_table.cpp does
// that for the sine table only).
//
// Teeth (each must be refuted, i.e. Z3 must find a counterexample, or the test fails): the ratio
// below 2^30 for every vector; the formula with base rounded down; the base always equal to the
// lower entry; the table bounded by 2^29 through entry 1025; the interpolation and product lemmas
// with a weight up to 2^20 + 1; and -x computed in I (not widened), which overflows at INT_MIN.
#include "prove.hpp"

#include <antkit/kernel/angle.hpp>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

using namespace antkit::proofs;
namespace kn = antkit::kernel;

namespace {

// The code's terms, rebuilt with the operations of atan2_raw (angle.hpp) line by line, so that
// each is the very Z3 term the code formed (rebuild() checks the result's id).
template <class W>
struct Atan2Terms {
  W n, d, divisor;   // the fold; divisor = D = d, or 1 at the origin
  W dividend, d2;    // what div_round_half_up divides: t = 2 (n 2^30) + D by 2D
  W ratio;           // its rounded quotient
  U32 index, weight; // the interpolation position u = ratio (as U32) split 10 | 20 bits
  W lo, hi, exact;   // the two entries (widened) and interpolate_exact's result
  U32 base, result;
  // The obligations of the rounding line (base = narrow((exact + 2^19) >> 20)): the narrowing
  // needs the interpolation lemma, so they are proved after it (see prove_format).
  std::vector<z3::expr> rounding_obligations;
};

template <class I, class W>
Atan2Terms<W> rebuild(Session& s, const I& y, const I& x) {
  namespace ops = kn::ops;
  using ops::add, ops::shl, ops::shr, ops::widen, ops::narrow, ops::neg, ops::band, ops::sub;
  using ops::wrap_sub, ops::wrap_add, ops::lookup;
  const W wx = widen<W>(x);
  const W wy = widen<W>(y);
  const W ax = select(x < I{0}, neg(wx), wx);
  const W ay = select(y < I{0}, neg(wy), wy);
  const Bool steep = ay > ax;
  const W n = select(steep, ax, ay);
  const W d = select(steep, ay, ax);
  const Bool origin = d == W{0};
  const W divisor = select(origin, W{1}, d);
  const W scaled = shl(n, 30);
  const W ratio = kn::div_round_half_up(scaled, divisor);
  // div_round_half_up's own terms (fixed.hpp): the divisor is positive, so np = n 2^30, dp = D.
  const Bool negative = divisor < W{0};
  const W dp = select(negative, neg(divisor), divisor);
  const W np = select(negative, neg(scaled), scaled);
  const W dividend = add(shl(np, 1), dp);
  const W d2 = shl(dp, 1);
  s.clear_obligations(); // the code's own, recorded again: proved with the code's
  const U32 u = narrow<U32>(ratio);
  const W exact = kn::interpolate_exact<W>(kn::angle_tables::kAtanUnits, u);
  s.clear_obligations();
  // interpolate_exact's own terms (angle.hpp).
  const U32 index = shr(u, kn::kWeightBits);
  const U32 weight = band(u, sub(shl(U32{1}, kn::kWeightBits), U32{1}));
  const W lo = widen<W>(lookup(kn::angle_tables::kAtanUnits, index));
  const W hi = widen<W>(lookup(kn::angle_tables::kAtanUnits, wrap_add(index, U32{1})));
  s.clear_obligations();
  const U32 base = narrow<U32>(shr(add(exact, shl(W{1}, kn::kWeightBits - 1)), kn::kWeightBits));
  std::vector<z3::expr> rounding;
  for (const auto& ob : s.obligations()) rounding.push_back(ob.holds);
  const U32 octant = select(steep, wrap_sub(shl(U32{1}, 30), base), base);
  const U32 half = select(x < I{0}, wrap_sub(shl(U32{1}, 31), octant), octant);
  const U32 full = select(y < I{0}, wrap_sub(U32{0}, half), half);
  const U32 result = select(origin, U32{0}, full);
  s.clear_obligations();
  return {n, d, divisor, dividend, d2, ratio, index, weight, lo, hi, exact, base, result, rounding};
}

// The documented formula, from the code's ratio (whose rounding ratio_rounds_half_up proves), in W.
// Not under a Specification: its operations record obligations like the code's, and
// formula_is_exact proves them, so each W-bit value below is the integer it names.
// round_half_up adds 2^19 before the shift; the teeth pass false (floor).
template <class I, class W>
U32 atan2_formula(const I& y, const I& x, const W& ratio, bool round_half_up,
                  std::vector<z3::expr>* exact_term = nullptr) {
  const W ax = select(x < I(0), W(0) - W(x), W(x));
  const W ay = select(y < I(0), W(0) - W(y), W(y));
  const Bool steep = ay > ax;
  const U32 r32(ratio);
  const U32 i = r32 >> 20;
  const U32 w = r32 & U32((1u << 20) - 1u);
  const W lo(antkit::proofs::lookup(kn::angle_tables::kAtanUnits, i));
  const W hi(antkit::proofs::lookup(kn::angle_tables::kAtanUnits, i + U32(1)));
  const W exact = (lo << 20) + (hi - lo) * W(w);
  if (exact_term != nullptr) exact_term->push_back(exact.expr());
  const W base = (exact + (round_half_up ? W(1 << 19) : W(0))) >> 20;
  const W quarter = W(1) << 30, half = W(1) << 31, turn = W(1) << 32;
  const W octant = select(steep, quarter - base, base);
  const W angle = select(x < I(0), select(y < I(0), half + octant, half - octant),
                         select(y < I(0), turn - octant, octant));
  // The result is angle mod 2^32: the conversion to U32 keeps the low 32 bits (2^32 -> 0).
  const U32 angle32(angle);
  const Bool origin = ax == W(0) && ay == W(0);
  return select(origin, U32(0), angle32);
}

// The table lemmas (proved first in each format's Session), instantiated at one index term.
void table_facts(Session& s, const U32& i) {
  z3::context& c = s.ctx();
  const z3::expr t = table_array(kn::angle_tables::kAtanUnits, 32);
  const z3::expr lo = z3::select(t, i.expr());
  const z3::expr hi = z3::select(t, (i + U32(1)).expr());
  const z3::expr in = z3::ule(i.expr(), c.bv_val(1024, 32));
  s.fact(z3::implies(in, z3::ule(lo, hi) && z3::ule(lo, c.bv_val(1u << 29, 32))));
}

void prove_table_lemmas(Prover& p) {
  const U32 i = U32::var("i");
  const U32 lo = antkit::proofs::lookup(kn::angle_tables::kAtanUnits, i);
  const U32 hi = antkit::proofs::lookup(kn::angle_tables::kAtanUnits, i + U32(1));
  p.assume(i <= U32(1024));
  p.claim("atan.table.monotone (i <= 1024: entry i <= entry i + 1)", lo <= hi);
  p.claim("atan.table.bounded (i <= 1024: 0 <= entry i <= 2^29)", lo <= U32(1u << 29));
  // Teeth: entry 1025 = atan(1025/1024) is past 1/8 turn.
  p.refute("atan.table.teeth: bounded by 2^29 through entry 1025", hi <= U32(1u << 29));
  p.reset_domain();
  p.claim("atan.table.ends (entry 0 = 0, entry 1024 = 2^29)",
          antkit::proofs::lookup(kn::angle_tables::kAtanUnits, U32(0)) == U32(0) &&
              antkit::proofs::lookup(kn::angle_tables::kAtanUnits, U32(1024)) == U32(1u << 29));
}

// The product q 2D in the division's definition becomes an unknown M, given back as the
// monotonicity lemma's instances at c = -1, 1, 2^30 - 1, 2^30 + 1 (c 2D written as shifts and an
// addition). Returns M, the quotient and the divisor as the definition has them (2N bits).
struct Generalised {
  z3::expr M, q, dd;
};
Generalised generalise_division(Session& s) {
  std::vector<Generalised> found;
  for (std::size_t i = 0; i < s.facts().size(); ++i) {
    if (auto prod = first_product(s.facts()[i])) {
      const unsigned w = prod->get_sort().bv_size();
      const z3::expr M = s.ctx().bv_const(s.fresh("M").c_str(), w);
      const z3::expr q = prod->arg(0), dd = prod->arg(1);
      s.substitute(*prod, M);
      const z3::expr pos = z3::sgt(dd, s.ctx().bv_val(0, w));
      const z3::expr dd30 = z3::shl(dd, s.ctx().bv_val(30, w));
      const std::vector<std::pair<std::int64_t, z3::expr>> constants{
          {-1, -dd}, {1, dd}, {(1 << 30) - 1, dd30 - dd}, {(1 << 30) + 1, dd30 + dd}};
      for (const auto& [cst, cd] : constants) {
        const z3::expr c = s.ctx().bv_val(cst, w);
        s.fact(z3::implies(pos, z3::implies(M > cd, q > c) && z3::implies(M < cd, q < c)));
      }
      found.push_back({M, q, dd});
    }
  }
  if (found.size() != 1) {
    std::cout << "FAILED   expected one abstracted division, found " << found.size() << "\n";
    std::exit(1);
  }
  return found[0];
}

// The product lemma (atan.product.in_range, over the reals) as a fact on an interpolant's product
// term (hi - lo) w, the one multiplication of two unknowns in atan2_raw and in the formula. Added
// only once the product's own obligation (no signed overflow) is proved for every input: then the
// product's W-bit value is the integer product the lemma speaks of.
void product_fact(Session& s, const z3::expr& product) {
  z3::context& c = s.ctx();
  const unsigned n = product.get_sort().bv_size();
  const z3::expr d = product.arg(0), w = product.arg(1);
  const auto pow2 = [&](int k) { return z3::shl(c.bv_val(1, n), c.bv_val(k, n)).simplify(); };
  s.fact(z3::implies(z3::sle(-pow2(32), d) && z3::sle(d, pow2(32)) && z3::sle(c.bv_val(0, n), w) &&
                         z3::sle(w, pow2(20)),
                     z3::sle(-pow2(52), product) && z3::sle(product, pow2(52))));
}

// Proves `obligations` in two phases: those that do not mention the product (hi - lo) w of `term`
// first (among them the product's own, no signed overflow), then, with product_fact, those that do
// (the interpolant's sum). Without the fact the SAT solver must bound a multiplier's output to
// prove the sum does not overflow (11 s for q31 in one run; the same step of the Q31.32 sine did
// not finish in 10 minutes). Returns false if a phase failed. `obligations` is taken by value: the
// caller may pass s.obligations() itself, which this clears.
bool prove_around_product(Session& s, Prover& p, const std::string& name,
                          std::vector<Session::Obligation> obligations, const z3::expr& term) {
  const std::optional<z3::expr> product = first_product(term);
  if (!product) {
    std::cout << "FAILED   " << name << ": no product (hi - lo) w in the interpolant\n";
    std::exit(1);
  }
  s.clear_obligations(); // (the caller may pass s.obligations() itself)
  std::vector<Session::Obligation> later;
  for (const auto& ob : obligations) {
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

template <class I, class W, int N>
void prove_format(Session& s, Prover& p, const std::string& fmt) {
  using S = Int<2 * N, true>; // the width of the division's definition: nothing in it wraps
  const I y = I::var("y"), x = I::var("x");
  const U32 r = kn::atan2_raw<I, W, U32>(y, x);
  const std::vector<Session::Obligation> code_obligations = s.obligations();
  s.clear_obligations();
  const Generalised g = generalise_division(s);
  const Atan2Terms<W> t = rebuild<I, W>(s, y, x);
  if (!z3::eq(t.result.expr(), r.expr())) {
    std::cout << "FAILED   the rebuilt terms are not the code's (angle.hpp changed?)\n";
    std::exit(1);
  }
  const auto& division = *s.signed_divisions().begin();
  if (s.signed_divisions().size() != 1 ||
      division.first.first != Z3_get_ast_id(s.ctx(), t.dividend.expr()) ||
      division.first.second != Z3_get_ast_id(s.ctx(), t.d2.expr())) {
    std::cout << "FAILED   the code's division is not t / 2D as rebuilt\n";
    std::exit(1);
  }
  const W q(division.second.first), rem(division.second.second);

  // The table lemmas at the code's index (instances of claims proved for every index).
  table_facts(s, t.index);

  // A claim proved for every input is then kept as a fact (Prover::keep: scoped to the domain it
  // was proved under, true since it was just proved), so that later checks need not re-derive it
  // from the division's definition (256-bit for q31).
  const auto keep = [&](const std::string& name, const Bool& c) {
    p.keep("atan2." + fmt + "." + name, c);
  };

  // The ratio, first: everything after the division depends on its range. M = q 2D by the
  // definition of division (generalised: see generalise_division).
  const S M{Int<2 * N, true>(g.M)};
  const S dd{Int<2 * N, true>(g.dd)};
  keep("ratio_divides (t = 2^31 n + D, divisor 2D, D = max(|x|, |y|) or 1)",
       t.dividend == (t.n << 31) + t.divisor && t.d2 == (t.divisor << 1) &&
           t.divisor == select(t.d == W(0), W(1), t.d) && t.n <= t.divisor);
  keep("ratio_is_the_quotient (no floor correction: remainder >= 0)", t.ratio == q && W(0) <= rem);
  p.claim("atan2." + fmt + ".ratio_rounds_half_up (ratio 2D <= 2^31 n + D < ratio 2D + 2D)",
          dd == S(t.d2) && M <= S(t.dividend) && S(t.dividend) < M + dd);
  keep("ratio_in_range (0 <= ratio <= 2^30)", W(0) <= t.ratio && t.ratio <= (W(1) << 30));
  keep("ratio_exact_on_axes_and_diagonals (n = 0: 0; n = D: 2^30)",
       (t.n != W(0) || t.ratio == W(0)) && (t.n != t.divisor || t.ratio == (W(1) << 30)));
  p.refute("atan2." + fmt + ".teeth: ratio < 2^30 for every vector", t.ratio < (W(1) << 30));

  // Lists (1) and (2) (see the top): every obligation of the code but the rounding line's, among
  // them that the interpolant's operations never wrap and its reads are in range.
  std::vector<Session::Obligation> rounding_line, up_to_interpolant;
  for (const auto& ob : code_obligations) {
    bool deferred = false;
    for (const auto& e : t.rounding_obligations) deferred = deferred || z3::eq(e, ob.holds);
    (deferred ? rounding_line : up_to_interpolant).push_back(ob);
  }
  if (!prove_around_product(s, p, "atan2." + fmt + ".no_undefined_behaviour", up_to_interpolant,
                            t.exact.expr()))
    return; // the interpolation fact below rests on these
  // The interpolation lemma on the code's interpolant: true of its W-bit terms because they were
  // just proved not to wrap (for every input), so each is the integer the lemma speaks of.
  {
    const Bool premises = t.lo <= t.hi && t.weight <= U32(1u << 20);
    const Bool between = (t.lo << 20) <= t.exact && t.exact <= (t.hi << 20);
    s.clear_obligations(); // the fact's own shifts: lo, hi < 2^32, so << 20 never wraps in W
    s.fact(z3::implies(premises.expr(), between.expr()));
  }
  // Three steps kept as facts, so that the narrowing below is linear from the facts.
  keep("index_at_most_1024", t.index <= U32(1024));
  keep("entries_ordered (lo <= hi)", t.lo <= t.hi);
  keep("interpolant_between_entries (lo 2^20 <= exact <= hi 2^20)",
       (t.lo << 20) <= t.exact && t.exact <= (t.hi << 20));
  s.clear_obligations();
  for (const auto& ob : rounding_line) s.oblige(ob.what, ob.holds);
  p.no_undefined_behaviour("atan2." + fmt + ".no_undefined_behaviour (the rounding line)");

  std::vector<z3::expr> spec_exact;
  const U32 spec = atan2_formula<I, W>(y, x, t.ratio, true, &spec_exact);
  prove_around_product(s, p, "atan2." + fmt + ".formula_is_exact", s.obligations(),
                       spec_exact.front());
  p.claim("atan2." + fmt + ".formula", r == spec);
  p.claim("atan2." + fmt + ".base_between_entries (lo <= base <= hi, 0 <= base <= 2^29)",
          U32(t.lo) <= t.base && t.base <= U32(t.hi) && t.base <= U32(1u << 29));
  p.refute("atan2." + fmt + ".teeth: the formula with base rounded down",
           r == atan2_formula<I, W>(y, x, t.ratio, false));
  p.take_obligations(); // the teeth's formula: the same operations as the one proved
  p.refute("atan2." + fmt + ".teeth: base is the lower entry", t.base == U32(t.lo));

  // Exact values.
  const I zero(0);
  p.assume(x == zero && y == zero);
  p.claim("atan2." + fmt + ".origin (atan2(0, 0) = 0)", r == U32(0));
  p.reset_domain();
  const U32 q1(1u << 30), q2(1u << 31), q3(3u << 30);
  p.claim("atan2." + fmt + ".axes (every magnitude: 0, 2^30, 2^31, 3 2^30)",
          (!(y == zero && x > zero) || r == U32(0)) && (!(x == zero && y > zero) || r == q1) &&
              (!(y == zero && x < zero) || r == q2) && (!(x == zero && y < zero) || r == q3));
  const W wx(x), wy(y);
  const W ax = select(x < zero, W(0) - wx, wx), ay = select(y < zero, W(0) - wy, wy);
  s.clear_obligations(); // |x|, |y| in W: the formula's, proved above
  const U32 o(1u << 29);
  p.assume(ax == ay && ax != W(0));
  p.claim("atan2." + fmt + ".diagonals (|x| = |y| != 0: 1, 3, 5, 7 times 2^29 by quadrant)",
          (!(x > zero && y > zero) || r == o) && (!(x < zero && y > zero) || r == U32(3) * o) &&
              (!(x < zero && y < zero) || r == U32(5) * o) &&
              (!(x > zero && y < zero) || r == U32(7) * o));
  p.reset_domain();

  // Teeth: |x| computed in I instead of W overflows at INT_MIN.
  const I narrow_neg = zero - x;
  (void)narrow_neg;
  p.refute("atan2." + fmt + ".teeth: -x in I (not widened) is defined", p.take_obligations());
}

void prove_lemmas(Session& s, Prover& p) {
  z3::context& c = s.ctx();
  {
    const z3::expr q = c.int_const("q"), d = c.int_const("d"), k = c.int_const("c");
    p.claim_over_integers(
        "atan.division.monotonicity_lemma",
        z3::implies(d > 0, z3::implies(q * d > k * d, q > k) && z3::implies(q * d < k * d, q < k)));
  }
  const z3::expr lo = c.real_const("lo"), hi = c.real_const("hi"), w = c.real_const("w");
  const z3::expr step = c.real_val(1 << 20);
  const z3::expr e = lo * step + (hi - lo) * w;
  const z3::expr between = lo * step <= e && e <= hi * step;
  p.claim_over_reals("atan.interpolation.between_entries",
                     z3::implies(lo <= hi && 0 <= w && w <= step, between));
  p.refute_over_reals("atan.interpolation.teeth: weight up to 2^20 + 1",
                      z3::implies(lo <= hi && 0 <= w && w <= step + 1, between));
  const z3::expr d = c.real_const("d");
  const z3::expr d_max = c.real_val(static_cast<std::int64_t>(1) << 32);
  const z3::expr p_max = c.real_val(static_cast<std::int64_t>(1) << 52);
  const z3::expr product_in_range = -p_max <= d * w && d * w <= p_max;
  p.claim_over_reals(
      "atan.product.in_range",
      z3::implies(-d_max <= d && d <= d_max && 0 <= w && w <= step, product_in_range));
  p.refute_over_reals(
      "atan.product.teeth: weight up to 2^20 + 1",
      z3::implies(-d_max <= d && d <= d_max && 0 <= w && w <= step + 1, product_in_range));
}

} // namespace

int main(int argc, char** argv) {
  const std::string part = argc > 1 ? argv[1] : "i32";
  if (part != "all" && part != "i32" && part != "q31") {
    std::cerr << "usage: proof_z3_angle_atan2 [i32 | q31 | all]\n";
    return 2;
  }
  int failed = 0;
  {
    Session s;
    Prover p(s);
    prove_lemmas(s, p);
    failed |= p.result();
  }
  const auto run = [&failed](auto prove) {
    Session s;
    Prover p(s);
    prove_table_lemmas(p);
    prove(s, p);
    failed |= p.result();
  };
  if (part == "all" || part == "i32")
    run([](Session& s, Prover& p) { prove_format<I32, I64, 64>(s, p, "i32"); });
  if (part == "all" || part == "q31")
    run([](Session& s, Prover& p) { prove_format<I64, I128, 128>(s, p, "q31"); });
  return failed;
}
