// Online stopping rule (issue 8, item 5): see stopping.hpp for the derivation.
#include <algorithm>
#include <antkit/algorithms/wide_to_double.hpp>
#include <antkit/buffon/stopping.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/int_ops.hpp>
#include <array>
#include <string>

namespace antkit::buffon {

namespace {

constexpr std::uint64_t kD = kPrecisionDenominator;
constexpr int kK = PrecisionMonitor::kBatches;

using u128 = antkit::kernel::uint128;      // int_ops.hpp: __int128, or soft::Int on 32-bit
using U256 = std::array<std::uint64_t, 4>; // little-endian 64-bit limbs

U256 mul(u128 a, u128 b) {
  const std::uint64_t a0 = static_cast<std::uint64_t>(a), a1 = static_cast<std::uint64_t>(a >> 64);
  const std::uint64_t b0 = static_cast<std::uint64_t>(b), b1 = static_cast<std::uint64_t>(b >> 64);
  U256 out{0, 0, 0, 0};
  auto add_at = [&out](int limb, u128 v) {
    for (int i = limb; i < 4 && v != 0; ++i) {
      const u128 s =
          static_cast<u128>(out[static_cast<std::size_t>(i)]) + static_cast<std::uint64_t>(v);
      out[static_cast<std::size_t>(i)] = static_cast<std::uint64_t>(s);
      v = (v >> 64) + (s >> 64);
    }
  };
  add_at(0, static_cast<u128>(a0) * b0);
  add_at(1, static_cast<u128>(a0) * b1);
  add_at(1, static_cast<u128>(a1) * b0);
  add_at(2, static_cast<u128>(a1) * b1);
  return out;
}

bool leq(const U256& x, const U256& y) {
  for (int i = 3; i >= 0; --i) {
    const auto k = static_cast<std::size_t>(i);
    if (x[k] != y[k]) return x[k] < y[k];
  }
  return true;
}

void check_precision(std::uint32_t p) {
  if (p < 1 || p >= kD)
    throw kernel::InputError("precision", "the relative precision must be in (0, 1)");
}

// 10 sum x_i^2 - (sum x_i)^2 = K (K - 1) s^2: never negative (Cauchy-Schwarz). Each x < 2^54, so
// every square < 2^108 and K times their sum < 2^112.
u128 spread_of(std::span<const std::uint64_t, kK> x, std::uint64_t n) {
  u128 squares = 0;
  for (std::uint64_t v : x) squares += static_cast<u128>(v) * v;
  return kK * squares - static_cast<u128>(n) * n;
}

} // namespace

bool precision_met(std::span<const std::uint64_t, kK> rows,
                   std::span<const std::uint64_t, kK> columns, std::uint32_t precision_millionths) {
  check_precision(precision_millionths);
  std::uint64_t n = 0;
  for (std::uint64_t v : rows) n += v;
  if (n == 0) return false;
  // W = 9 V < 2^113; floored at 9 N (V >= N, Poisson).
  const u128 w = std::max(spread_of(rows, n) + spread_of(columns, n), static_cast<u128>(9) * n);
  const u128 p = precision_millionths;
  // Left: 5118 (D + p)^2 < 2^13 2^42 = 2^55, times W < 2^113: < 2^168. Right: 9000 p^2 < 2^54,
  // times N^2 < 2^108: < 2^162. Both exact in 256 bits.
  const u128 coeff_left = static_cast<u128>(PrecisionMonitor::kZSquaredMilli) * (kD + p) * (kD + p);
  const u128 coeff_right = static_cast<u128>(9000) * p * p;
  return leq(mul(coeff_left, w), mul(coeff_right, static_cast<u128>(n) * n));
}

PrecisionMonitor::PrecisionMonitor(std::uint32_t precision_millionths,
                                   std::uint64_t visit1_segments)
    : p_(precision_millionths), segments1_(std::max<std::uint64_t>(visit1_segments, 1)) {
  check_precision(precision_millionths);
}

void PrecisionMonitor::crossing(std::uint64_t segment) {
  // Row i holds segments [i S / K, (i + 1) S / K): the K equal runs of visit 1 (S < 2^58).
  const std::uint64_t row = std::min<std::uint64_t>(segment * kK / segments1_, kK - 1);
  ++rows_[row];
  ++n_;
}

bool PrecisionMonitor::end_step() {
  if (++steps_ % kBlockSteps != 0) return false;
  prefix_.push_back(n_);
  const std::size_t blocks = prefix_.size() - 1;
  if (blocks % kK != 0) return false;
  // Column j: the crossings of blocks [j m, (j + 1) m), m = blocks / K.
  const std::size_t m = blocks / kK;
  std::uint64_t columns[kK];
  for (std::size_t j = 0; j < kK; ++j) columns[j] = prefix_[(j + 1) * m] - prefix_[j * m];
  using algorithms::to_double;
  spread_ = {n_, n_ ? to_double(spread_of(rows_, n_)) / 9.0 : 0.0,
             n_ ? to_double(spread_of(columns, n_)) / 9.0 : 0.0};
  reached_ = precision_met(rows_, columns, p_);
  return reached_;
}

bool first_visit_met(std::span<const std::uint64_t, kK> runs, std::uint32_t precision_millionths) {
  check_precision(precision_millionths);
  std::uint64_t twice_s = 0;
  for (std::uint64_t v : runs) twice_s += v;
  const std::uint64_t s = twice_s / 2;
  if (s == 0) return false;
  // W = 9 V_S = 10 sum R^2 - (2 S)^2 < 2^112, floored at 9 S.
  const u128 w = std::max(spread_of(runs, twice_s), static_cast<u128>(9) * s);
  const u128 p = precision_millionths;
  // Left < 2^55 2^112 = 2^167; right: 18000 p^2 < 2^55, times S^2 < 2^108. Exact in 256 bits.
  const u128 coeff_left = static_cast<u128>(PrecisionMonitor::kZSquaredMilli) * (kD + p) * (kD + p);
  const u128 coeff_right = static_cast<u128>(18000) * p * p;
  return leq(mul(coeff_left, w), mul(coeff_right, static_cast<u128>(s) * s));
}

FirstVisitMonitor::FirstVisitMonitor(std::uint32_t precision_millionths)
    : p_(precision_millionths) {
  check_precision(precision_millionths);
}

void FirstVisitMonitor::crossing(std::uint64_t earlier) {
  // The current step is steps_ + 1, its segment steps_: one end in its block, one in earlier's.
  ++blocks_.back();
  ++blocks_[static_cast<std::size_t>(earlier / kBlockSteps)];
  ++s_;
}

bool FirstVisitMonitor::end_step() {
  if (++steps_ % kBlockSteps != 0) return false;
  const std::size_t full = blocks_.size(); // blocks completed, the last one included
  blocks_.push_back(0);
  if (full % kK != 0) return false;
  const std::size_t m = full / kK;
  std::uint64_t runs[kK] = {};
  for (std::size_t g = 0; g < kK; ++g)
    for (std::size_t b = g * m; b < (g + 1) * m; ++b) runs[g] += blocks_[b];
  variance_ = s_ ? algorithms::to_double(spread_of(runs, 2 * s_)) / 9.0 : 0.0;
  reached_ = first_visit_met(runs, p_);
  return reached_;
}

std::uint32_t parse_precision(std::string_view text) {
  const std::string shown(text);
  auto bad = [&shown]() {
    return kernel::InputError("precision", "the precision must be a decimal in (0, 1) with at "
                                           "most six digits after the point, got '" +
                                               shown + "'");
  };
  std::size_t i = 0;
  std::uint64_t whole = 0;
  bool any_digit = false;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9') {
    whole = whole * 10 + static_cast<std::uint64_t>(text[i] - '0');
    if (whole >= 1) throw bad(); // P < 1
    any_digit = true;
    ++i;
  }
  std::uint64_t fraction = 0;
  int decimals = 0;
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') {
      if (++decimals > 6) throw bad();
      fraction = fraction * 10 + static_cast<std::uint64_t>(text[i] - '0');
      any_digit = true;
      ++i;
    }
  }
  if (!any_digit || i != text.size()) throw bad();
  for (int d = decimals; d < 6; ++d) fraction *= 10;
  if (fraction == 0) throw bad(); // P > 0
  return static_cast<std::uint32_t>(fraction);
}

PrecisionRule parse_rule(std::string_view text) {
  for (const PrecisionRule r :
       {PrecisionRule::markers, PrecisionRule::online, PrecisionRule::fixed})
    if (text == rule_name(r)) return r;
  std::string shown(text.substr(0, 64));
  for (char& ch : shown)
    if (static_cast<unsigned char>(ch) < 0x20 || static_cast<unsigned char>(ch) >= 0x7f) ch = '?';
  throw kernel::InputError("stopping rule", "expected 'markers', 'online' or 'fixed', got '" +
                                                shown + (text.size() > 64 ? "...'" : "'"));
}

std::string_view rule_name(PrecisionRule rule) noexcept {
  switch (rule) {
  case PrecisionRule::markers:
    return "markers";
  case PrecisionRule::online:
    return "online";
  case PrecisionRule::fixed:
    break;
  }
  return "fixed";
}

} // namespace antkit::buffon
