#pragma once
// Points and segments in fixed-point coordinates. (Shape only; the exact integer predicates are
// being written in this file next.)
#include <antkit/kernel/fixed.hpp>

namespace antkit::kernel {

struct FxPoint {
  Fx x;
  Fx y;
  friend constexpr bool operator==(FxPoint, FxPoint) = default;
};

struct FxSegment {
  FxPoint a;
  FxPoint b;
  friend constexpr bool operator==(FxSegment, FxSegment) = default;
};

} // namespace antkit::kernel
