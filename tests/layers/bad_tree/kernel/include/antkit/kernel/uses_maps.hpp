#pragma once
// A planted arrow against the layer order (tests/layers: layers.includes.teeth): the kernel may use
// nothing but the standard library. And a planted word: the kernel is integers only.
#include <antkit/maps/map_io.hpp>
double planted_ratio(int a, int b);
