// layers.fence.algorithms (tests/layers/CMakeLists.txt): compiled with exactly the include roots of
// the algorithms layer's target. The headers of the layers it uses are found; the last include,
// of a layer it may not use, must not be.
#include <antkit/kernel/grid.hpp>
#include <antkit/stc/world.hpp>
// Of a layer this one may not use:
#include <antkit/geometry/arena.hpp>
