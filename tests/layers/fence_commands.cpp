// layers.fence.commands (tests/layers/CMakeLists.txt): compiled with exactly the include roots of
// the commands layer's target. The headers of the layers it uses are found; the last include,
// of a layer it may not use, must not be.
#include <antkit/commands/json.hpp>
#include <antkit/commands/options.hpp>
#include <antkit/devices/log.hpp>
#include <antkit/testing/stc.hpp>
// Of a layer this one may not use:
#include <antkit/experiments/verdict.hpp>
