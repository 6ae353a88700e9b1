#pragma once
#include <cstdint>
#include <functional>

namespace tv {

/// Stable handle to an item in a World. A removed item's handle never becomes valid again,
/// even when its storage is reused (the generation changes; a slot whose 2^32 generations are
/// used up is retired, never reused).
struct ItemId {
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  std::uint32_t index = kNone;
  std::uint32_t generation = 0;

  [[nodiscard]] constexpr bool valid() const { return index != kNone; }
  friend constexpr bool operator==(ItemId a, ItemId b) = default;
};

}  // namespace tv

template <>
struct std::hash<tv::ItemId> {
  std::size_t operator()(tv::ItemId id) const noexcept {
    return std::hash<std::uint64_t>{}((std::uint64_t{id.generation} << 32) | id.index);
  }
};
