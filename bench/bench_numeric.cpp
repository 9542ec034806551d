// Speed of the kernel's numbers: fixed-point multiply, divide and square root, binary-angle sine
// and atan2, fixed-point uniforms. Each loop feeds its result back into the next input so the
// compiler cannot hoist or vectorise the operation away; the numbers are latencies per call.
#include <antkit/kernel/angle.hpp>
#include <antkit/kernel/fixed.hpp>
#include <antkit/kernel/fixed_random.hpp>
#include <benchmark/benchmark.h>
#include <cstdint>

namespace {

using antkit::kernel::Angle;
using antkit::kernel::Fixed;
using antkit::kernel::Fx;
using F64 = Fixed<std::int64_t, 32>;

template <class X>
void BM_FixedMul(benchmark::State& state) {
  X x = X::from_ratio(3, 2);
  const X k = X::from_ratio(2, 3);
  for (auto _ : state) {
    x = x * k + X::one(); // stays near 3: x -> 2x/3 + 1
    benchmark::DoNotOptimize(x);
  }
}
BENCHMARK(BM_FixedMul<Fx>)->Name("fx_mul/Q15.16");
BENCHMARK(BM_FixedMul<F64>)->Name("fx_mul/Q31.32");

template <class X>
void BM_FixedDiv(benchmark::State& state) {
  X x = X::from_ratio(3, 2);
  const X k = X::from_ratio(3, 2);
  for (auto _ : state) {
    x = x / k + X::one(); // stays near 3
    benchmark::DoNotOptimize(x);
  }
}
BENCHMARK(BM_FixedDiv<Fx>)->Name("fx_div/Q15.16");
BENCHMARK(BM_FixedDiv<F64>)->Name("fx_div/Q31.32");

template <class X>
void BM_FixedSqrt(benchmark::State& state) {
  X x = X::from_int(1000);
  for (auto _ : state) {
    x = sqrt(x) + X::from_int(900); // stays near 930
    benchmark::DoNotOptimize(x);
  }
}
BENCHMARK(BM_FixedSqrt<Fx>)->Name("fx_sqrt/Q15.16");
BENCHMARK(BM_FixedSqrt<F64>)->Name("fx_sqrt/Q31.32");

void BM_Sin(benchmark::State& state) {
  Angle a = Angle::from_raw(12345);
  for (auto _ : state) {
    const Fx s = sin(a);
    a += Angle::from_raw(0x9E3779B9u + static_cast<std::uint32_t>(s.raw()));
    benchmark::DoNotOptimize(a);
  }
}
BENCHMARK(BM_Sin)->Name("sin/Fx");

void BM_SinCos(benchmark::State& state) {
  Angle a = Angle::from_raw(12345);
  for (auto _ : state) {
    const Fx s = sin(a), c = cos(a);
    a += Angle::from_raw(0x9E3779B9u + static_cast<std::uint32_t>(s.raw() ^ c.raw()));
    benchmark::DoNotOptimize(a);
  }
}
BENCHMARK(BM_SinCos)->Name("sin+cos/Fx");

void BM_Atan2(benchmark::State& state) {
  std::int32_t x = 123456, y = -654321;
  for (auto _ : state) {
    const Angle a = antkit::kernel::atan2(y, x);
    x = static_cast<std::int32_t>(a.raw() >> 8) - 8000000;
    y = static_cast<std::int32_t>(a.raw() >> 9) + 12345;
    benchmark::DoNotOptimize(x);
  }
}
BENCHMARK(BM_Atan2)->Name("atan2/int32");

void BM_Uniform(benchmark::State& state) {
  antkit::kernel::Stream s(1, 2, 3, 4, 5);
  const Fx lo = Fx::from_int(-200), hi = Fx::from_int(200);
  for (auto _ : state) benchmark::DoNotOptimize(uniform(s, lo, hi));
}
BENCHMARK(BM_Uniform)->Name("uniform/Fx[-200,200]");

} // namespace
