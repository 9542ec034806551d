// layers.fence.geometry (tests/layers/CMakeLists.txt): compiled with exactly the include roots of
// the geometry layer's target. The headers of the layers it uses are found; the last include,
// of a layer it may not use, must not be: the grid map files are the maps layer's, not geometry's.
#include <antkit/geometry/arena.hpp>
#include <antkit/kernel/grid.hpp>
// Of a layer this one may not use:
#include <antkit/maps/map_io.hpp>
