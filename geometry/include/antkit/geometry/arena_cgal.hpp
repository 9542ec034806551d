#pragma once
// The CGAL side of an Arena, for code that needs the exact polygon itself: the geometry layer's
// sources and the tests that hold the kit against CGAL as an oracle. Everything else includes
// <antkit/geometry/arena.hpp>, which compiles without CGAL (DESIGN.md: CGAL stays inside geometry).
//
// The number type is CGAL::Gmpq (exact rationals): every coordinate an arena holds is a terminating
// decimal (read from WKT) or a multiple of 2^-16 (built by a family builder), and every predicate
// and construction on it is exact. Simple_cartesian<Gmpq> rather than Epeck: the arenas are small
// (hundreds of vertices), the rational coordinates must be reachable for the exact "p/q" area and
// the exact WKT writer, and a lazy kernel would only add a layer between us and them.
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/Simple_cartesian.h>
#include <antkit/geometry/arena.hpp>
#include <string>
#include <vector>

namespace antkit::geometry {

using ExactNumber = CGAL::Gmpq;
using ExactKernel = CGAL::Simple_cartesian<ExactNumber>;
using ExactPoint = ExactKernel::Point_2;
using ExactSegment = ExactKernel::Segment_2;
using ExactPolygon = CGAL::Polygon_2<ExactKernel>;
using ExactPolygonWithHoles = CGAL::Polygon_with_holes_2<ExactKernel>;

// The exact polygon with holes behind an arena: outer boundary counter-clockwise, holes clockwise,
// no repeated closing vertex (Arena's invariants, see arena.hpp).
[[nodiscard]] const ExactPolygonWithHoles& exact_polygon(const Arena& arena);

// Validates `polygon` (see arena.hpp, "Validity"), normalises its orientation, and wraps it.
// Throws kernel::InputError(where, ...) naming the ring and vertex that break a rule.
[[nodiscard]] Arena make_arena(ExactPolygonWithHoles polygon, const std::string& where);

// Exact rational helpers shared by the WKT writer, the rasterizer and the wall conversion.
[[nodiscard]] CGAL::Gmpz floor_of(const ExactNumber& q);       // largest integer <= q
[[nodiscard]] CGAL::Gmpz ceil_of(const ExactNumber& q);        // smallest integer >= q
[[nodiscard]] std::string fraction_text(const ExactNumber& q); // "p/q" in lowest terms, q > 0
// The exact decimal expansion of q ("-12.5", "0.0001", "3"), or an empty string when q is not a
// terminating decimal (its reduced denominator has a prime factor other than 2 and 5).
[[nodiscard]] std::string decimal_text(const ExactNumber& q);

} // namespace antkit::geometry
