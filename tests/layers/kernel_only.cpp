// layers.fence.kernel_alone: compiled with nothing but the kernel's include root: every kernel
// header stands on the standard library alone.
#include <antkit/kernel/angle.hpp>
#include <antkit/kernel/fixed.hpp>
#include <antkit/kernel/fixed_random.hpp>
#include <antkit/kernel/grid.hpp>
#include <antkit/kernel/hash.hpp>
#include <antkit/kernel/input_error.hpp>
#include <antkit/kernel/int_ops.hpp>
#include <antkit/kernel/random.hpp>
#include <antkit/kernel/raster.hpp>
#include <antkit/kernel/segment.hpp>
#include <antkit/kernel/text_lines.hpp>
