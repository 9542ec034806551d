#include <antkit/kernel/random.hpp>
#include <antkit/stc/online.hpp>

namespace antkit::stc {

namespace {
constexpr std::size_t kInitialSlots = 64; // a power of two
}

CellMemory::CellMemory() : keys_(kInitialSlots, 0), slots_(kInitialSlots, kEmpty) {}

std::size_t CellMemory::bytes() const noexcept {
  return keys_.size() * (sizeof(std::uint64_t) + sizeof(std::uint32_t)) + tiles_.size() * 256;
}

std::uint8_t* CellMemory::tile_for(Cell c, bool create) {
  const auto tx = static_cast<std::uint32_t>(c.x >> kTileBits);
  const auto ty = static_cast<std::uint32_t>(c.y >> kTileBits);
  const std::uint64_t key = (std::uint64_t{tx} << 32) | ty;
  if (key == last_key_) return last_tile_;
  std::size_t mask = keys_.size() - 1;
  std::size_t i = static_cast<std::size_t>(kernel::mix64(key)) & mask;
  while (slots_[i] != kEmpty) {
    if (keys_[i] == key) {
      last_key_ = key;
      last_tile_ = tiles_[slots_[i]].data();
      return last_tile_;
    }
    i = (i + 1) & mask;
  }
  if (!create) return nullptr;
  // Keep the load factor at most 1/2 so that probes stay short.
  if (2 * (tiles_.size() + 1) > keys_.size()) {
    std::vector<std::uint64_t> old_keys(keys_.size() * 2, 0);
    std::vector<std::uint32_t> old_slots(slots_.size() * 2, kEmpty);
    old_keys.swap(keys_);
    old_slots.swap(slots_);
    mask = keys_.size() - 1;
    for (std::size_t j = 0; j < old_keys.size(); ++j) {
      if (old_slots[j] == kEmpty) continue;
      std::size_t k = static_cast<std::size_t>(kernel::mix64(old_keys[j])) & mask;
      while (slots_[k] != kEmpty) k = (k + 1) & mask;
      keys_[k] = old_keys[j];
      slots_[k] = old_slots[j];
    }
    i = static_cast<std::size_t>(kernel::mix64(key)) & mask;
    while (slots_[i] != kEmpty) i = (i + 1) & mask;
  }
  keys_[i] = key;
  slots_[i] = static_cast<std::uint32_t>(tiles_.size());
  tiles_.emplace_back();
  tiles_.back().fill(0);
  // emplace_back may have moved every tile: the cached pointer is refreshed here.
  last_key_ = key;
  last_tile_ = tiles_.back().data();
  return last_tile_;
}

namespace {
constexpr std::size_t offset_in_tile(Cell c) noexcept {
  constexpr std::int32_t m = (1 << CellMemory::kTileBits) - 1;
  return static_cast<std::size_t>(((c.y & m) << CellMemory::kTileBits) | (c.x & m));
}
} // namespace

std::uint8_t CellMemory::get(Cell c) {
  const std::uint8_t* tile = tile_for(c, false);
  return tile ? tile[offset_in_tile(c)] : std::uint8_t{0};
}

bool CellMemory::set(Cell c, std::uint8_t value) {
  tile_for(c, true)[offset_in_tile(c)] = value;
  return true;
}

template class BasicOnlineStc<CellMemory>;

} // namespace antkit::stc
