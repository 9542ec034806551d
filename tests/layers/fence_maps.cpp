// layers.fence.maps (tests/layers/CMakeLists.txt): compiled with exactly the include roots of
// the maps layer's target. The headers of the layers it uses are found; the last include,
// of a layer it may not use, must not be: the map files need no CGAL arena.
#include <antkit/io/atomic_file.hpp>
#include <antkit/kernel/grid.hpp>
#include <antkit/maps/map_io.hpp>
// Of a layer this one may not use:
#include <antkit/geometry/arena.hpp>
