#pragma once
// Conversions between the kernel's fixed-point numbers and binary angles and floating point, for
// the reporting side (statistics, fits, plots, parsing of human-written parameters). Nothing a
// controller decides may come back through these functions after a run has started (DESIGN.md,
// rule 1): a parameter is converted once, up front, and from then on it is a fixed-point value.
#include <antkit/kernel/angle.hpp>
#include <antkit/kernel/fixed.hpp>
#include <antkit/kernel/input_error.hpp>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>

namespace antkit::geometry {

// The value of x: exact whenever the raw value has at most 53 significant bits (always for Fx,
// and for Fixed<std::int64_t, 32> in (-2^21, 2^21)); otherwise rounded to nearest by the cast.
template <class Rep, int F>
double to_double(kernel::Fixed<Rep, F> x) {
  return std::ldexp(static_cast<double>(x.raw()), -F);
}

// The representable number nearest to v (ties away from zero, as std::round). A NaN, an infinity
// or a value outside the format's range is bad input: InputError naming `where` (an option or a
// file position), so the command exits 2 with one clear message.
template <class FixedT>
FixedT fixed_from_double(double v, const std::string& where = "") {
  using Rep = typename FixedT::rep;
  const double scaled = std::round(std::ldexp(v, FixedT::frac_bits)); // exact scaling by 2^F
  const double limit = std::ldexp(1.0, FixedT::bits - 1);             // 2^(N-1), exact
  if (!std::isfinite(scaled) || scaled < -limit || scaled >= limit) {
    std::ostringstream msg;
    msg.precision(17);
    msg << "the value " << v << " is outside the fixed-point range ["
        << -std::ldexp(1.0, FixedT::bits - 1 - FixedT::frac_bits) << ", "
        << std::ldexp(1.0, FixedT::bits - 1 - FixedT::frac_bits) << ")";
    throw kernel::InputError(where, msg.str());
  }
  return FixedT::from_raw(static_cast<Rep>(scaled));
}

// An angle in radians in [-pi, pi) and in degrees in [-180, 180): exact conversions of the signed
// unit count, then one rounding.
inline double radians(kernel::Angle a) {
  return static_cast<double>(a.signed_raw()) * (3.14159265358979323846 / 2147483648.0);
}
inline double degrees(kernel::Angle a) {
  return static_cast<double>(a.signed_raw()) * (180.0 / 2147483648.0);
}

// The binary angle nearest to the given direction, modulo a turn; a NaN or infinity is bad input.
inline kernel::Angle angle_from_degrees(double deg, const std::string& where = "") {
  if (!std::isfinite(deg)) throw kernel::InputError(where, "an angle must be a finite number");
  const double turns = std::remainder(deg, 360.0) / 360.0; // in [-1/2, 1/2], exact remainder
  const auto units = static_cast<std::int64_t>(std::round(std::ldexp(turns, 32)));
  return kernel::Angle::from_raw(static_cast<std::uint32_t>(units));
}
inline kernel::Angle angle_from_radians(double rad, const std::string& where = "") {
  if (!std::isfinite(rad)) throw kernel::InputError(where, "an angle must be a finite number");
  return angle_from_degrees(rad * (180.0 / 3.14159265358979323846), where);
}

} // namespace antkit::geometry
