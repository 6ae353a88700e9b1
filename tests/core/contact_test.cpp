// Specification of contact events and ground state (tv/contact.hpp): begin / persist / end per
// pair in add order, read from the world as it stands after any move — with the naive way (the
// per-move collision lists) as the negative control — and what a body stands on.

#include "tv/contact.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tv/error.hpp"
#include "tv/mover.hpp"
#include "tv/solid.hpp"
#include "tv/world.hpp"

namespace {

using tv::ContactEvent;
using tv::ContactOptions;
using tv::ContactPhase;
using tv::Contacts;
using tv::GroundKind;
using tv::ItemId;
using tv::Vec2;
using tv::World;

// "begin 1", "persist 2"...: an update's events as words, by the other's slot index.
std::vector<std::string> words(std::span<const ContactEvent> es) {
  std::vector<std::string> out;
  for (const ContactEvent& e : es) {
    const char* p = e.phase == ContactPhase::begin     ? "begin"
                    : e.phase == ContactPhase::persist ? "persist"
                                                       : "end";
    out.push_back(std::string(p) + " " + std::to_string(e.other.index));
  }
  return out;
}
using W = std::vector<std::string>;
// Updates' events in one line: "begin 0 | persist 0, begin 1 | ...".
std::string line(const std::vector<W>& updates) {
  std::string out;
  for (std::size_t i = 0; i < updates.size(); ++i) {
    if (i) out += " | ";
    for (std::size_t j = 0; j < updates[i].size(); ++j) out += (j ? ", " : "") + updates[i][j];
  }
  return out;
}

// Two floor tiles side by side and a body standing on the first, walking right 4 px a move:
//
//        +--+
//        |b |                     body {4, 88, 8, 12} (slot 2)
//   +----------------+----------------+
//   |   tile 0       |   tile 1       |   {0, 100, 16, 16}, {16, 100, 16, 16}
//   +----------------+----------------+
struct Walk {
  static constexpr tv::Rect kTile0{0, 100, 16, 16}, kTile1{16, 100, 16, 16}, kBody{4, 88, 8, 12};
  World world{16};
  ItemId tile0 = world.add(kTile0);
  ItemId tile1 = world.add(kTile1);
  ItemId body = world.add(kBody);
};

TEST(Contacts, ARestingBodyWalkingAlongAFloorKeepsItsContactAndMeetsTheNextTileOnce) {
  Walk s;
  Contacts contacts;
  std::vector<W> got;
  for (int i = 0; i < 5; ++i) {
    const Vec2 p = s.world.rect(s.body).position();
    const tv::MoveResult r = s.world.move(s.body, {p.x + 4, p.y});
    got.push_back(words(contacts.update(s.world, s.body, {}, r.collisions)));
  }
  // x: 8 (tile 0), 12 (both), 16 (right edge on the seam: tile 0 only by its corner), 20, 24.
  EXPECT_EQ(line(got), "begin 0 | persist 0, begin 1 | end 0, persist 1 | persist 1 | persist 1");
}

TEST(Contacts, NegativeControlContactsFromTheMoveListsFlickerOnARestingBody) {
  // The naive way: a pair is in contact when the move's collision list names it. Walking level
  // along a floor meets nothing (no collision), so the floor's contact ends after every move in
  // which gravity did not press the body down — here every other move (it stays on tile 0).
  Walk s;
  std::vector<ItemId> before;
  int ends = 0, begins = 0;
  for (int i = 0; i < 6; ++i) {
    const Vec2 p = s.world.rect(s.body).position();
    const double fall = i % 2 == 0 ? 1.0 : 0.0;  // gravity pressed the body down, or it did not
    const tv::MoveResult r = s.world.move(s.body, {p.x + 0.5, p.y + fall});
    std::vector<ItemId> now;
    for (const tv::Collision& c : r.collisions) now.push_back(c.other);
    for (ItemId b : before)
      if (std::find(now.begin(), now.end(), b) == now.end()) ++ends;
    for (ItemId n : now)
      if (std::find(before.begin(), before.end(), n) == before.end()) ++begins;
    before = now;
  }
  EXPECT_EQ(ends, 3) << "the naive contact ended while the body stood on the floor throughout";
  EXPECT_EQ(begins, 3);

  // The same moves through tv::Contacts: one begin, then persist.
  Walk t;
  Contacts contacts;
  int tEnds = 0, tBegins = 0;
  for (int i = 0; i < 6; ++i) {
    const Vec2 p = t.world.rect(t.body).position();
    const tv::MoveResult r = t.world.move(t.body, {p.x + 0.5, p.y + (i % 2 == 0 ? 1.0 : 0.0)});
    for (const ContactEvent& e : contacts.update(t.world, t.body, {}, r.collisions)) {
      tEnds += e.phase == ContactPhase::end;
      tBegins += e.phase == ContactPhase::begin;
    }
  }
  EXPECT_EQ(tEnds, 0);
  EXPECT_EQ(tBegins, 1);
}

TEST(Contacts, EventsComeInTheAddOrderOfTheOtherItemNotByPlaceOrDirection) {
  //        +----+
  //        | c  |         ceiling c {0, 0, 30, 10}   (added first)
  //   +---++----++---+
  //   | a || b  ||   |    a {0, 10, 10, 10} left wall (added third), body b {10, 10, 10, 10},
  //   +---++----++---+    right wall {20, 10, 10, 10} (added second)
  //        | f  |         floor f {0, 20, 30, 10}     (added fourth)
  //        +----+
  World w(8);
  const ItemId c = w.add({0, 0, 30, 10});
  const ItemId right = w.add({20, 10, 10, 10});
  const ItemId left = w.add({0, 10, 10, 10});
  const ItemId f = w.add({0, 20, 30, 10});
  const ItemId b = w.add({10, 10, 10, 10});
  Contacts contacts;
  const std::span<const ContactEvent> es = contacts.update(w, b);
  ASSERT_EQ(es.size(), 4u);
  EXPECT_EQ(es[0].other, c);
  EXPECT_EQ(es[0].normal, (Vec2{0, 1}));
  EXPECT_EQ(es[1].other, right);
  EXPECT_EQ(es[1].normal, (Vec2{-1, 0}));
  EXPECT_EQ(es[2].other, left);
  EXPECT_EQ(es[2].normal, (Vec2{1, 0}));
  EXPECT_EQ(es[3].other, f);
  EXPECT_EQ(es[3].normal, (Vec2{0, -1}));
  // Removing the walls ends their contacts in the same order, with their last normals.
  w.remove(right);
  w.remove(left);
  const std::span<const ContactEvent> gone = contacts.update(w, b);
  EXPECT_EQ(words(gone), (W{"persist 0", "end 1", "end 2", "persist 3"}));
  EXPECT_EQ(gone[1].normal, (Vec2{-1, 0}));
}

TEST(Contacts, ACornerAloneIsNoContactAndAnOverlapHasNoNormal) {
  //   +--+
  //   |a |         a {0, 0, 10, 10}; b {10, 10, 10, 10} meets it at one corner only;
  //   +--+--+      c {15, 15, 10, 10} overlaps b.
  //      |b |
  //      +--+
  World w(8);
  w.add({0, 0, 10, 10});
  const ItemId b = w.add({10, 10, 10, 10});
  const ItemId c = w.add({15, 15, 10, 10});
  Contacts contacts;
  const std::span<const ContactEvent> es = contacts.update(w, b);
  ASSERT_EQ(es.size(), 1u);
  EXPECT_EQ(es[0].other, c);
  EXPECT_EQ(es[0].normal, (Vec2{0, 0}));
}

TEST(Contacts, ACoinCrossedInPassingBeginsThenEnds) {
  //   body -> . . [coin] . . . |   a coin {40, 0, 4, 4} crossed by a body moving 100 px right
  World w(16);
  const ItemId coin = w.add({40, 0, 4, 4});
  const ItemId body = w.add({0, 0, 8, 8});
  const auto filter = [&](ItemId, ItemId other) {
    return other == coin ? tv::response::cross : tv::response::slide;
  };
  Contacts contacts;
  ContactOptions o;
  o.filter = filter;
  const tv::MoveResult r = w.move(body, {100, 0}, filter);
  ASSERT_EQ(r.collisions.size(), 1u);
  const std::span<const ContactEvent> es = contacts.update(w, body, o, r.collisions);
  ASSERT_EQ(words(es), (W{"begin 0"}));
  EXPECT_TRUE(es[0].met);
  EXPECT_EQ(es[0].normal, (Vec2{-1, 0}));
  EXPECT_EQ(words(contacts.update(w, body, o, w.move(body, {110, 0}, filter).collisions)),
            (W{"end 0"}));
  EXPECT_EQ(contacts.ground(body).kind, GroundKind::air) << "a coin is not ground";
}

TEST(Contacts, TheFilterDecidesIgnoredItemsAreNoContactCrossedItemsAreNoGround) {
  //   +--+
  //   |b |       body on a floor {0, 10, 20, 4}
  //   +--------+
  World w(8);
  const ItemId floor = w.add({0, 10, 20, 4});
  const ItemId body = w.add({0, 0, 8, 10});
  Contacts contacts;
  ContactOptions o;
  tv::ResponseId answer = tv::response::ignore;
  const auto filter = [&](ItemId, ItemId) { return answer; };
  o.filter = filter;
  EXPECT_TRUE(contacts.update(w, body, o).empty());
  answer = tv::response::cross;
  EXPECT_EQ(words(contacts.update(w, body, o)), (W{"begin 0"}));
  EXPECT_EQ(contacts.ground(body).kind, GroundKind::air);
  answer = tv::response::slide;
  EXPECT_EQ(words(contacts.update(w, body, o)), (W{"persist 0"}));
  EXPECT_EQ(contacts.ground(body).kind, GroundKind::ground);
  EXPECT_EQ(contacts.ground(body).item, floor);
  EXPECT_EQ(contacts.ground(body).normal, (Vec2{0, -1}));
}

TEST(Contacts, EveryMoverGivesTheSameEventsForABodyLandingAndWalking) {
  // A body falls 15 px a move onto a floor, then walks on it pressed down: begin on landing,
  // persist after, with every swept mover (and the pixel mover). The discrete mover, the naive
  // negative control, teleports 15 px into the floor and is pushed out of its far side: its
  // contact ends (below).
  for (const std::string_view name : tv::moverNames()) {
    if (name == "discrete") continue;
    World w(16);
    const ItemId floor = w.add({0, 40, 200, 16});
    const ItemId body = w.add({10, 0, 8, 10});
    tv::Mover mover(tv::parseMover(name));
    Contacts contacts;
    std::vector<W> got;
    for (int i = 0; i < 4; ++i) {
      const Vec2 p = w.rect(body).position();
      const tv::MoveResult r = mover.move(w, body, {p.x + 3, p.y + 15});
      got.push_back(words(contacts.update(w, body, {}, r.collisions)));
    }
    // Bottom edge 10, 25, then 40: on the floor's top from the second move on.
    EXPECT_EQ(line(got), " | begin 0 | persist 0 | persist 0") << name;
    EXPECT_EQ(contacts.ground(body).item, floor) << name;
  }
  World w(16);
  w.add({0, 40, 200, 16});
  const ItemId body = w.add({10, 0, 8, 10});
  tv::Mover discrete(tv::parseMover("discrete"));
  Contacts contacts;
  std::vector<W> got;
  for (int i = 0; i < 4; ++i) {
    const Vec2 p = w.rect(body).position();
    got.push_back(words(
        contacts.update(w, body, {}, discrete.move(w, body, {p.x + 3, p.y + 15}).collisions)));
  }
  EXPECT_EQ(line(got), " | begin 0 | persist 0 | end 0")
      << "pushed out through the floor at y " << w.rect(body).y;
}

// [SECTION] ground ------------------------------------------------------------------------------

TEST(Ground, OnAMovingSolidTheGroundIsTheSolidWithItsVelocityOnAOneWayItsOwnKind) {
  //        +--+
  //        |r |          rider {20, 88, 8, 12}
  //   +------+--+-----+
  //   |  lift (solid) |  lift {0, 100, 48, 8}, moved up 5 px an update by tv::moveSolid
  //   +---------------+            +---------+
  //                                | one-way |  {100, 100, 48, 8}
  World w(32);
  const ItemId lift = w.add({0, 100, 48, 8});
  const ItemId plank = w.add({100, 100, 48, 8});
  const ItemId rider = w.add({20, 88, 8, 12});
  const ItemId walker = w.add({110, 88, 8, 12});
  const std::vector<ItemId> bodies{rider, walker}, solids{lift}, oneWay{plank};
  ContactOptions o;
  o.solids = solids;
  o.oneWay = oneWay;
  Contacts contacts;
  contacts.update(w, rider, o);
  EXPECT_EQ(contacts.ground(rider).kind, GroundKind::solid);
  EXPECT_EQ(contacts.ground(rider).velocity, (Vec2{0, 0})) << "a contact just begun";
  tv::SolidOptions so;
  so.bodies = bodies;
  (void)tv::moveSolid(w, lift, {0, 95}, so);
  contacts.update(w, rider, o);
  EXPECT_EQ(contacts.ground(rider).item, lift);
  EXPECT_EQ(contacts.ground(rider).velocity, (Vec2{0, -5}));
  contacts.update(w, walker, o);
  EXPECT_EQ(contacts.ground(walker).kind, GroundKind::oneWay);
  EXPECT_EQ(contacts.ground(walker).item, plank);
}

TEST(Ground, CoyoteTimeLastsTheGivenUpdatesAfterWalkingOffALedgeAndEndsOnAJump) {
  //   +--+
  //   |b | ->           body walks off the ledge's right end at 8 px an update, falling 1 px
  //   +-------+
  //   | ledge |         ledge {0, 10, 16, 10}
  //   +-------+
  for (const bool jump : {false, true}) {
    World w(16);
    const ItemId ledge = w.add({0, 10, 16, 10});
    const ItemId body = w.add({0, 0, 8, 10});
    ContactOptions o;
    o.coyoteUpdates = 3;
    Contacts contacts;
    std::vector<GroundKind> kinds;
    for (int i = 0; i < 6; ++i) {
      const Vec2 p = w.rect(body).position();
      const tv::MoveResult r = w.move(body, {p.x + 8, p.y + 1});
      contacts.update(w, body, o, r.collisions);
      if (jump && i == 2) contacts.jumped(body);
      kinds.push_back(contacts.ground(body).kind);
      if (kinds.back() == GroundKind::coyote) {
        EXPECT_EQ(contacts.ground(body).item, ledge);
      }
    }
    // x 8: on the ledge; x 16 and on: in the air.
    using K = GroundKind;
    if (!jump) {
      EXPECT_EQ(kinds,
                (std::vector<K>{K::ground, K::coyote, K::coyote, K::coyote, K::air, K::air}));
    } else {
      EXPECT_EQ(kinds, (std::vector<K>{K::ground, K::coyote, K::air, K::air, K::air, K::air}));
    }
  }
}

TEST(Ground, WithoutCoyoteTimeABodyIsInTheAirTheUpdateItLeaves) {
  World w(16);
  w.add({0, 10, 16, 10});
  const ItemId body = w.add({8, 0, 8, 10});
  Contacts contacts;
  contacts.update(w, body);
  EXPECT_EQ(contacts.ground(body).kind, GroundKind::ground);
  w.move(body, {16, 1});
  contacts.update(w, body);
  EXPECT_EQ(contacts.ground(body).kind, GroundKind::air);
  EXPECT_EQ(contacts.ground(body).updatesInAir, 1);
}

TEST(Contacts, BadInputIsRefusedNamingTheValueAndChangesNothing) {
  World w(16);
  const ItemId floor = w.add({0, 10, 16, 10});
  const ItemId body = w.add({0, 0, 8, 10});
  Contacts contacts;
  contacts.update(w, body);
  w.remove(floor);
  ContactOptions bad;
  bad.coyoteUpdates = -1;
  try {
    (void)contacts.update(w, body, bad);
    FAIL() << "a negative coyoteUpdates was accepted";
  } catch (const tv::Error& e) {
    EXPECT_NE(std::string(e.what()).find("coyoteUpdates"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)contacts.update(w, floor), tv::Error);
  ASSERT_EQ(contacts.current(body).size(), 1u) << "the refused calls changed nothing";
  EXPECT_EQ(words(contacts.forget(body)), (W{"end 0"}));
  EXPECT_TRUE(contacts.current(body).empty());
}

}  // namespace
