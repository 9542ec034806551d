#include <antkit/stc/ant.hpp>

namespace antkit::stc {

} // namespace antkit::stc
