// layers.fence.io (tests/layers/CMakeLists.txt): compiled with exactly the include roots of
// the io layer's target. The headers of the layers it uses are found; the last include,
// of a layer it may not use, must not be.
#include <antkit/io/atomic_file.hpp>
#include <antkit/kernel/input_error.hpp>
// Of a layer this one may not use:
#include <antkit/maps/map_io.hpp>
