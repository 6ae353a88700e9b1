#pragma once
#include <cstdint>
#include <functional>

namespace tv {

/// Stable handle to an item in a World. A removed item's handle never becomes valid again,
/// even when its storage is reused (the generation changes; a slot whose 2^32 generations are
/// used up is retired, never reused).
/// A default-constructed id is invalid: it names no item in any world.
struct ItemId {
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;  ///< the index of an invalid id
  std::uint32_t index = kNone;   ///< the item's slot in its world
  std::uint32_t generation = 0;  ///< the slot's use count when the item was added

  /// False for a default-constructed id (it may still name an item since removed).
  [[nodiscard]] constexpr bool valid() const { return index != kNone; }
  /// Same slot and generation.
  friend constexpr bool operator==(ItemId a, ItemId b) = default;
};

}  // namespace tv

/// @cond
// Hashing for unordered containers keyed by ItemId: not API of its own.
template <>
struct std::hash<tv::ItemId> {
  std::size_t operator()(tv::ItemId id) const noexcept {
    return std::hash<std::uint64_t>{}((std::uint64_t{id.generation} << 32) | id.index);
  }
};
/// @endcond
