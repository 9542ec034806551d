#pragma once
// A template copy of antkit::kernel::bounded_u32 (geometry/include/antkit/kernel/random.hpp), the
// one the Z3 proof proofs/z3/bounded_u32.cpp instantiates.
//
// Why a copy: the shipped function is written over std::uint32_t / std::uint64_t and branches with
// `if`, so it cannot be instantiated with the Z3 integer type, and proofs/ may not edit the kernel.
// The link between the two is TESTED correspondence (tests/proofs/test_bounded_u32_copy.cpp runs
// both on every x for several n and on random (x, n)), not a proof. Making the shipped function
// this template (instantiated with kernel integers) would make the Z3 proof a proof about shipped
// code.
//
// The copy keeps the shipped structure step by step: the 64-bit product, its low word, the
// short-circuit `low < n` before the (costly) remainder, then the threshold 2^32 mod n computed as
// (-n) % n in 32 bits. The two nested ifs become select(), which evaluates both arms: the remainder
// is therefore computed even when low >= n, which is harmless (n >= 1 is the domain, so % is
// defined) and which the machine version may skip without changing the result.
#include <cstdint>
#include <utility>

namespace antkit::proofs {

// The integer policy: 32- and 64-bit unsigned words, and the truth values their comparisons give.
struct MachineWords {
  using u32 = std::uint32_t;
  using u64 = std::uint64_t;
  using boolean = bool;
  static constexpr u32 select(bool c, u32 a, u32 b) { return c ? a : b; }
  static constexpr bool select(bool c, bool a, bool b) { return c ? a : b; }
};

// Returns (accepted, out): accepted is bounded_u32's return value, out what it writes on acceptance
// (the copy also returns the high word when it rejects; the shipped one leaves `out` untouched).
template <class W>
constexpr std::pair<typename W::boolean, typename W::u32> bounded_u32_t(typename W::u32 x,
                                                                        typename W::u32 n) {
  using u32 = typename W::u32;
  using u64 = typename W::u64;
  const u64 m = u64(x) * u64(n);
  const u32 low = u32(m);
  const u32 threshold = u32(u32(0) - n) % n; // 2^32 mod n
  const typename W::boolean rejected = W::select(low < n, low < threshold, false);
  const u32 out = u32(m >> 32);
  return {!rejected, out};
}

} // namespace antkit::proofs
