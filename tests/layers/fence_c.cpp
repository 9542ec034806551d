// layers.fence.c (tests/layers/CMakeLists.txt): compiled with exactly the include roots of
// the c layer's target. The headers of the layers it uses are found; the last include,
// of a layer it may not use, must not be.
#include <antkit/c/antkit.h>
// Of a layer this one may not use:
#include <antkit/maps/map_io.hpp>
