// layers.fence.experiments (tests/layers/CMakeLists.txt): compiled with exactly the include roots
// of the experiments layer's target. The headers of the layers it uses are found; the last include,
// of a layer it may not use, must not be.
#include <antkit/devices/log.hpp>
#include <antkit/experiments/verdict.hpp>
#include <antkit/testing/stc.hpp>
// Of a layer this one may not use:
#include <antkit/commands/json.hpp>
