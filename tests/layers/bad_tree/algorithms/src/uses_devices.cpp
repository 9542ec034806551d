// A planted arrow against the layer order (tests/layers: layers.includes.teeth): algorithms may
// use only the kernel.
#include <antkit/devices/log.hpp>
#include <antkit/kernel/fixed.hpp>
