#pragma once
// A planted arrow against the layer order (tests/layers: layers.includes.teeth): the kernel may use
// nothing but the standard library.
#include <antkit/maps/map_io.hpp>
