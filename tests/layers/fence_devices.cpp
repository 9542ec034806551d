// layers.fence.devices (tests/layers/CMakeLists.txt): compiled with exactly the include roots of
// the devices layer's target. The headers of the layers it uses are found; the last include,
// of a layer it may not use, must not be.
#include <antkit/devices/log.hpp>
#include <antkit/maps/map_io.hpp>
#include <antkit/stc/world.hpp>
// Of a layer this one may not use:
#include <antkit/testing/stc.hpp>
