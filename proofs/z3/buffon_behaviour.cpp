// Z3 proof: the shipped exploration behaviour of the Buffon controller (antkit::buffon::
// exploration_step, exploration.hpp, which ExplorationBehaviour::step runs with FxPolicy) keeps its
// state in range and is free of overflow, for every sensor input in [0, 1]^6 and every random draw.
//
// A proof about the shipped template: exploration_step<Z3Fx> below is the same source, with each
// Q15.16 number a 32-bit Z3 integer and each operation the same Fixed kernel the machine Fx calls
// (fx_add_raw, fx_sub_raw, fx_neg_raw, fx_mul_raw<int32, int64, 16>: Fixed's operators are
// exactly these). Two small pieces are written here rather than taken from the kernel: |x| is
// kernel::abs's one line (select(x < 0, neg x, x)) over the raw value, and select picks the raw.
// The step is branch-free, so one symbolic run covers every case.
//
// Domain (the invariant, raw Q15.16, one = 2^16): r in [-1, 1], w_l and w_r in [0, 1], every I_i
// in [0, 1], the draws n in [-0.4, 0.4] and n_bar in [0.3, 1] (their raw ranges, as
// kernel::uniform draws them).
//   behaviour.no_overflow        every int32/int64 operation of the step is defined (every product
//                                rounds into int32)
//   behaviour.state_in_range     r' in [-1, 1], w_l' and w_r' in [0, 1]   (so, by induction from
//                                the start r = w = 0, every reachable state is in the domain)
//   behaviour.w_below_one        w_l' < 1 and w_r' < 1: the upper clamp of w is never needed (at
//                                w = 1 the gain term vanishes and the decay pulls w down; below 1
//                                w + 0.5 (1 - w) - 0.1 w < 1), found when a teeth check of
//                                "w' <= 1 - 2^-16" could not be refuted
//   behaviour.turn_in_range      r_bar in [-1, 1]
//   behaviour.wheels_in_range    |m_l| <= 1 and |m_r| <= 1 (exactly, rounding included)
// Teeth (behaviour.teeth.*): |m_l| <= 1 - 2^-16 and |r'| <= 1 - 2^-16 must be refuted (the
// bounds are reached).
#include "prove.hpp"

#include <antkit/buffon/exploration.hpp>
#include <antkit/kernel/fixed.hpp>

using namespace antkit::proofs;
namespace k = antkit::kernel;

namespace {

struct Z3Fx {
  I32 raw;
  friend Z3Fx operator+(const Z3Fx& a, const Z3Fx& b) { return {k::fx_add_raw<I32>(a.raw, b.raw)}; }
  friend Z3Fx operator-(const Z3Fx& a, const Z3Fx& b) { return {k::fx_sub_raw<I32>(a.raw, b.raw)}; }
  Z3Fx operator-() const { return {k::fx_neg_raw<I32>(raw)}; }
  friend Z3Fx operator*(const Z3Fx& a, const Z3Fx& b) {
    return {k::fx_mul_raw<I32, I64, 16>(a.raw, b.raw)};
  }
  friend Bool operator<(const Z3Fx& a, const Z3Fx& b) { return a.raw < b.raw; }
  friend Bool operator>(const Z3Fx& a, const Z3Fx& b) { return a.raw > b.raw; }
};

struct Z3Policy {
  using num = Z3Fx;
  static Z3Fx select(const Bool& c, const Z3Fx& a, const Z3Fx& b) {
    return {antkit::proofs::select(c, a.raw, b.raw)};
  }
  static Z3Fx abs(const Z3Fx& x) {
    return {antkit::proofs::select(x.raw < I32(0), k::fx_neg_raw<I32>(x.raw), x.raw)};
  }
  static Z3Fx lift(k::Fx x) { return {I32(x.raw())}; }
};

} // namespace

int main() {
  Session s;
  Prover p(s);
  const I32 one(k::Fx::one_raw);
  const auto unit = [&](const Z3Fx& x) { return I32(0) <= x.raw && x.raw <= one; };
  const auto signed_unit = [&](const Z3Fx& x) { return I32(0) - one <= x.raw && x.raw <= one; };
  const Z3Fx r{I32::var("r")}, w_l{I32::var("w_l")}, w_r{I32::var("w_r")};
  std::array<Z3Fx, 6> I;
  for (int i = 0; i < 6; ++i) I[static_cast<std::size_t>(i)] = {I32::var("I" + std::to_string(i))};
  const Z3Fx n{I32::var("n")}, n_bar{I32::var("n_bar")};
  const I32 n_limit(antkit::buffon::detail::kNLimit.raw()),
      n_bar_low(antkit::buffon::detail::kNBarLow.raw());
  Bool domain = signed_unit(r) && unit(w_l) && unit(w_r) && I32(0) - n_limit <= n.raw &&
                n.raw <= n_limit && n_bar_low <= n_bar.raw && n_bar.raw <= one;
  for (const Z3Fx& x : I) domain = domain && unit(x);
  s.clear_obligations();
  p.assume(domain);

  const auto out = antkit::buffon::exploration_step<Z3Policy>(r, w_l, w_r, I, n, n_bar);
  p.no_undefined_behaviour("behaviour.no_overflow");
  p.claim("behaviour.state_in_range", signed_unit(out.r) && unit(out.w_l) && unit(out.w_r));
  p.claim("behaviour.w_below_one", out.w_l.raw < one && out.w_r.raw < one);
  p.claim("behaviour.turn_in_range", signed_unit(out.r_bar));
  p.claim("behaviour.wheels_in_range", signed_unit(out.m_l) && signed_unit(out.m_r));
  p.refute("behaviour.teeth: |m_l| <= 1 - 2^-16",
           I32(1) - one <= out.m_l.raw && out.m_l.raw <= one - I32(1));
  p.refute("behaviour.teeth: |r'| <= 1 - 2^-16",
           I32(1) - one <= out.r.raw && out.r.raw <= one - I32(1));
  return p.result();
}
