// layers.fence.mpi (tests/layers/CMakeLists.txt): compiled with exactly the include roots of
// the mpi layer's target. The headers of the layers it uses are found; the last include,
// of a layer it may not use, must not be.
#include <antkit/mpi/session.hpp>
// Of a layer this one may not use:
#include <antkit/kernel/hash.hpp>
