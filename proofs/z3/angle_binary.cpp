// Z3 proof: binary-angle arithmetic (angle.hpp) over the shipped policy operations, instantiated
// with 32-bit Z3 words, for every angle:
//   angle.group.*          wrap_add / wrap_sub (Angle's + and -) form the group Z / 2^32:
//                          associative, commutative, 0 is the identity, wrap_sub(0, a) the inverse,
//                          and a - b == a + (-b).
//   angle.nearest_bearing  nearest_bearing_raw(a) = k in [0, 8) with a - k 2^29 (mod 2^32, read as
//                          signed) in [-2^28, 2^28): the nearest bearing, ties counter-clockwise.
// Negative check: the bearing window without its counter-clockwise tie is refuted.
// (sin_raw and cos_raw are proved in angle_sine.cpp, the degree/radian conversions in
// angle_conversions.cpp.)
#include "prove.hpp"

#include <antkit/kernel/angle.hpp>

using namespace antkit::proofs;
namespace kn = antkit::kernel;

int main() {
  Session s;
  Prover p(s);
  using kn::ops::wrap_add, kn::ops::wrap_sub;
  const U32 a = U32::var("a"), b = U32::var("b"), c = U32::var("c");
  p.claim("angle.group.associative", wrap_add(wrap_add(a, b), c) == wrap_add(a, wrap_add(b, c)));
  p.claim("angle.group.commutative", wrap_add(a, b) == wrap_add(b, a));
  p.claim("angle.group.identity", wrap_add(a, U32(0)) == a);
  p.claim("angle.group.inverse", wrap_add(a, wrap_sub(U32(0), a)) == U32(0));
  p.claim("angle.group.sub_is_add_inverse", wrap_sub(a, b) == wrap_add(a, wrap_sub(U32(0), b)));

  const U32 k = kn::nearest_bearing_raw(a);
  const I32 off(wrap_sub(a, k << 29));
  p.claim("angle.nearest_bearing (k < 8, offset in [-2^28, 2^28))",
          k < U32(8) && I32(-(1 << 28)) <= off && off < I32(1 << 28));
  p.refute("angle.nearest_bearing: offset in (-2^28, 2^28) is false (the tie goes ccw)",
           I32(-(1 << 28)) < off && off < I32(1 << 28));

  return p.result();
}
