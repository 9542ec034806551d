#pragma once
// Arenas as Well-Known Text (OGC Simple Features, the 2D subset an arena needs):
//
//   POLYGON ((x y, x y, ..., x y), (hole), ...)
//   MULTIPOLYGON (((x y, ...), (hole), ...))
//
// Reading: keywords in any case; whitespace (spaces, tabs, newlines) anywhere between tokens;
// every ring closed (last point equal to the first) with at least three distinct points; numbers
// are decimals (`-12`, `0.25`, `.5`, `1e-3`) read EXACTLY as rationals, so nothing is lost between
// a file and the arena. A MULTIPOLYGON must hold exactly one polygon: an arena is one connected
// region (the robot must be able to reach all of it), so a second polygon is rejected at its
// position. Rejected too: EMPTY, Z/M coordinates, coordinates of magnitude 32768 or more (walls
// must fit the kernel's Q15.16 numbers), numbers with more than 100 digits or an exponent beyond
// +-100. The polygon is then validated as arena.hpp says (simple rings, holes strictly inside and
// apart, orientation normalised). Errors: kernel::InputError "SOURCE:LINE:COL: ..." (columns in
// bytes).
//
// Writing: `POLYGON ((x y, ...), ...)` with the outer ring first, each ring closed, each coordinate
// its exact decimal expansion (shortest, no exponent). read_wkt(write_wkt(a)) == a, exactly.
#include <antkit/geometry/arena.hpp>
#include <filesystem>
#include <string>
#include <string_view>

namespace antkit::geometry {

[[nodiscard]] Arena read_wkt(std::string_view text, const std::string& source = "WKT");
// Reads a file (at most 64 MiB); a file that cannot be read is an InputError naming it.
[[nodiscard]] Arena read_wkt_file(const std::filesystem::path& path);

// Throws std::invalid_argument if a coordinate has no finite decimal expansion (only possible for
// an arena made from arbitrary rationals through arena_cgal.hpp: builders and read_wkt never do).
[[nodiscard]] std::string write_wkt(const Arena& arena);

} // namespace antkit::geometry
