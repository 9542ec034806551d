#include <antkit/algorithms/controller.hpp>

namespace antkit::algorithms {

std::uint32_t version_number() noexcept {
  return ANTKIT_VERSION_MAJOR * 10000u + ANTKIT_VERSION_MINOR * 100u + ANTKIT_VERSION_PATCH;
}

} // namespace antkit::algorithms
