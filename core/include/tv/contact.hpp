#pragma once
/// Contact events and ground state: what a platformer asks after each move of a body — which
/// items it began touching, still touches, stopped touching, and what it stands on.
///
/// A body's contacts are read from the world as it stands after the move, not from the move's
/// collision list: a body resting on a floor and walking along it meets nothing in a move that
/// goes level (the list is empty), yet it still touches the floor. A game that derives contacts
/// from the per-move lists sees that contact end and begin again every time a move reports no
/// collision (tests/core/contact_test.cpp shows it flicker).
///
///     tv::Contacts contacts;
///     world.move(player, goal, filter);               // or any mover, moveSolid, a batch...
///     for (const tv::ContactEvent& e : contacts.update(world, player, {filter}))
///       if (e.phase == tv::ContactPhase::begin) onTouch(e.other, e.normal);
///     if (contacts.ground(player).kind != tv::GroundKind::air) canJump = true;
///
/// Definitions:
/// - `other` is in contact with `item` when their rects overlap, or share an edge over a
///   positive length (a corner alone is not a contact), or rest one on the other as the core's
///   contact places them (tv::placeBefore: bit for bit whenever a double allows, else one
///   rounding step short); and the filter does not answer `ignore` for (item, other). Items the
///   move met on its way (the `met` collisions: a coin crossed in passing) are contacts of that
///   update too, so a pass-through is a begin, then an end at the next update.
/// - Events of one update come in the add order of `other` (never address or hash order); an
///   item that has left the world since the last update ends its contacts in the same order.
/// - The ground is the contact under the body (normal (0, −1)) that its filter does not cross:
///   of several, the one it overlaps most horizontally, ties to the earlier added. Its kind is
///   `oneWay` or `solid` when the game listed the item in ContactOptions, `ground` otherwise.
///   Its velocity is how far it moved since the previous update of this body (world units per
///   update), 0 when the contact just began.
/// - Coyote time: for ContactOptions::coyoteUpdates updates after the body left the ground
///   without jumping (Contacts::jumped), its ground kind is `coyote` with the last ground's item.
///
/// Bad input: an unknown body throws tv::Error naming it, changing nothing.

#include <cstdint>
#include <span>
#include <vector>

#include "tv/geometry.hpp"
#include "tv/item.hpp"
#include "tv/response.hpp"

namespace tv {

class World;

/// Where a contact is in its life.
enum class ContactPhase : std::uint8_t {
  begin,    ///< touching now, not at the previous update
  persist,  ///< touching at both
  end,      ///< touching at the previous update, not now (or the item has left the world)
};

/// One contact event of a body.
struct ContactEvent {
  ItemId item;   ///< the body that was updated
  ItemId other;  ///< what it touches (or touched)
  ContactPhase phase = ContactPhase::begin;
  /// Axis normal from `other` towards `item`: (0, −1) when the body stands on `other`, (0, 1)
  /// under a ceiling, (±1, 0) against a side; (0, 0) when they overlap. For a contact met in
  /// passing, the collision's normal; for an end, the normal it had at its last update.
  Vec2 normal;
  /// The contact came from the move's collision list only (met in passing, not touching now).
  bool met = false;
};

/// What a body stands on.
enum class GroundKind : std::uint8_t {
  air,     ///< nothing under it
  ground,  ///< an item not listed as one-way or solid
  oneWay,  ///< an item listed in ContactOptions::oneWay (a jump-through platform)
  solid,   ///< an item listed in ContactOptions::solids (a lift, a moving platform)
  coyote,  ///< in the air, but left the ground at most ContactOptions::coyoteUpdates ago
};

/// The ground under a body after its last update.
struct Ground {
  GroundKind kind = GroundKind::air;
  ItemId item;    ///< what it stands on (for coyote: what it last stood on); invalid in the air
  Vec2 normal;    ///< (0, −1) on the ground; (0, 0) in the air or in coyote time
  Vec2 velocity;  ///< the ground's displacement since the previous update, per update
  int updatesInAir = 0;  ///< updates since it last stood on something (0 while it stands)
};

/// How Contacts::update reads the world.
struct ContactOptions {
  /// The game's filter for the body: `ignore` is no contact, `cross` is a contact but not ground.
  Filter filter;
  std::span<const ItemId> oneWay;  ///< items that are one-way platforms (ground kind oneWay)
  std::span<const ItemId> solids;  ///< items that are moving solids (ground kind solid)
  /// Updates after leaving the ground (without Contacts::jumped) during which the ground kind is
  /// `coyote`. 0 (default) is no coyote time. Range [0, 2^20].
  int coyoteUpdates = 0;
};

/// Contacts of the bodies a game updates, kept from one update to the next.
class Contacts {
 public:
  /// Reads `item`'s contacts in `world` now and returns the events since its previous update
  /// (valid until the next call on this object). `met`: the collisions of the move just made,
  /// whose items count as contacts of this update. The first update of a body begins every
  /// contact it has. Throws tv::Error for an unknown item or bad coyoteUpdates, changing nothing.
  std::span<const ContactEvent> update(const World& world, ItemId item,
                                       const ContactOptions& o = {},
                                       std::span<const Collision> met = {});
  /// Stops tracking `item` (removed from the world, say): an end for each of its contacts.
  std::span<const ContactEvent> forget(ItemId item);
  /// The ground under `item` at its last update (air for a body never updated).
  [[nodiscard]] Ground ground(ItemId item) const;
  /// The body jumped: its coyote time ends now (it keeps its ground if it still stands on it).
  void jumped(ItemId item);
  /// The contacts `item` had at its last update, in the add order of `other` (phase begin or
  /// persist).
  [[nodiscard]] std::span<const ContactEvent> current(ItemId item) const;

 private:
  struct Touch {
    ContactEvent event;
    Rect otherRect;       // where `other` stood at the update
    std::uint64_t order;  // its add order
    bool crossed;         // the filter answered cross: a contact, not ground
  };
  struct Body {
    ItemId id;
    std::vector<Touch> touches;
    std::vector<ContactEvent> view;  // touches' events, for current()
    Ground ground;
    bool tracked = false;
    ItemId lastGround;    // what it last stood on (coyote time's ground)
    bool jumped = false;  // jumped since it last stood: no coyote time
  };
  Body* find(ItemId item);
  [[nodiscard]] const Body* find(ItemId item) const;

  std::vector<Body> bodies_;  // by slot index
  std::vector<Touch> next_;
  std::vector<ContactEvent> events_;
  std::vector<ItemId> found_;
};

}  // namespace tv
