#pragma once
// Named arena specs (DESIGN.md, Files and formats): a family name, then optional KEY=VALUE
// parameters after a colon, separated by commas, no spaces:
//
//   standard                      the circle of diameter 100 (paper 000's standard arena)
//   circle:d=100                  (a) d = diameter, or area=A; n = vertex count
//   square:area=7854              (b) area=A, or side=S, or d=D (the area of the circle of diameter
//                                     D: the paper's "square counterpart"); default: standard area
//   ellipse:area=7854,e=0.968     (c) e is required; area defaults to the standard area; n
//   barrier-i:len=0.4             (d) `|` barrier; len = length / diameter, required; t = thickness
//                                     (default 1); d = arena diameter (default 100); n
//   barrier-plus:len=0.4          (e) `+` barrier; same parameters
//   ring:area=7854,ratio=0.5      (f) ratio = inner radius / outer radius; n
//   plus:area=7854,arm=0.3333     (g) arm = arm width / overall span
//   obstacles:area=7854,size=5    (h) size = obstacle diameter; n
//
// Every area defaults to the standard area pi * 50^2 (Figure 3(c)-(h) share it). Numbers are
// decimals (`100`, `0.4`, `7.854e3`); n is a whole number. The ranges are the builders'
// (arena.hpp). Errors are kernel::InputError at "SPEC:1:COL" (COL counts bytes from 1), or at
// `where` if given.
#include <antkit/geometry/arena.hpp>
#include <map>
#include <string>
#include <string_view>

namespace antkit::geometry {

struct ArenaSpec {
  std::string family;                   // as written: "circle", "barrier-i", ...
  std::map<std::string, double> params; // as written, before defaults
};

// Parses the text of a spec (family known, parameter names known for that family, no parameter
// twice, every value a finite decimal). Does not build the arena.
[[nodiscard]] ArenaSpec parse_arena_spec(std::string_view text, const std::string& where = "SPEC");

struct NamedArena {
  Arena arena;
  double ideal_area; // the area of the ideal (curved, unrounded) shape the spec names
};

// Parses and builds; out-of-range values are reported at the column of the value.
[[nodiscard]] NamedArena build_arena_spec(std::string_view text, const std::string& where = "SPEC");

} // namespace antkit::geometry
