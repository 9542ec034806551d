// Z3 proof: the shipped Buffon crossing detector (antkit::buffon::detector_step, detector.hpp, the
// template CrossingDetector::update runs with std::int32_t and bool) keeps its leaky integrator in
// [0, 1] and thresholds it as documented. A proof about the shipped template, instantiated here
// with 32-bit Z3 integers and Z3 truth values; it has no branches (select and boolean algebra), so
// one symbolic run covers every state and bit.
//
// Domain (the invariant): raw level y in [0, one] (one = 2^16, Q15.16), any output `high`, any bit.
// Induction: the detector starts at y = 0, low (in the domain), and detector.level_in_unit shows a
// step keeps y in [0, one].
//   detector.no_overflow           every int32 operation of the step is defined
//   detector.level_in_unit         0 <= y' <= one
//   detector.level_is_the_floor    y' = floor((y + b one) / 2): 2y' <= y + b one < 2y' + 2
//   detector.count_needs_half      a count implies y' >= one / 2
//   detector.count_only_from_low   a count implies high was false and high' is true
//   detector.falls_only_below_a_quarter   high and not high'  implies  y' < one / 4
//   detector.holds_in_the_band     one / 4 <= y' < one / 2  implies  high' == high
// Together: counts happen only on low-to-high transitions; after one the output stays high until a
// step leaves y below 1/4; so between two counts y falls below 1/4 (at most one count per entry
// into the band y >= 1/2).
// Teeth (detector.teeth.*): bounds one ulp tighter must be refuted: a count needs y' >= one/2 + 1,
// a fall needs y' < one/4 - 1, and y' <= one - 1.
#include "prove.hpp"

#include <antkit/buffon/detector.hpp>

using namespace antkit::proofs;

int main() {
  Session s;
  Prover p(s);
  constexpr int one = antkit::kernel::Fx::one_raw;
  const I32 y = I32::var("y");
  const Bool high = Bool::var("high"), bit = Bool::var("bit");
  const Bool domain = I32(0) <= y && y <= I32(one);
  p.assume(domain);

  const auto next = antkit::buffon::detector_step<I32, Bool>(y, high, bit);
  p.no_undefined_behaviour("detector.no_overflow");
  const I32 b = select(bit, I32(one), I32(0));
  p.claim("detector.level_in_unit", I32(0) <= next.y && next.y <= I32(one));
  p.claim("detector.level_is_the_floor",
          I32(2) * next.y <= y + b && y + b < I32(2) * next.y + I32(2));
  p.claim("detector.count_needs_half", !next.count || next.y >= I32(one / 2));
  p.claim("detector.count_only_from_low", !next.count || (!high && next.high));
  p.claim("detector.falls_only_below_a_quarter", !(high && !next.high) || next.y < I32(one / 4));
  p.claim("detector.holds_in_the_band",
          !(I32(one / 4) <= next.y && next.y < I32(one / 2)) || next.high == high);

  p.refute("detector.teeth: a count needs y' >= one/2 + 1",
           !next.count || next.y >= I32(one / 2 + 1));
  p.refute("detector.teeth: a fall needs y' < one/4 - 1",
           !(high && !next.high) || next.y < I32(one / 4 - 1));
  p.refute("detector.teeth: y' <= one - 1", next.y <= I32(one - 1));
  return p.result();
}
