// Specification of the built-in one-way response (response::oneway, tv::onewayResponse): a
// platform blocks only a body that meets its top from entirely above it — exact, at any speed,
// with every swept mover and with bump's rules — passes a body jumping up through it without
// snagging, and lets a body drop through when the filter answers `cross`. The negative controls:
// the platform answered `slide` (a jump stops under it) and the "within 1 px" test some games
// write (it lands a body that was inside the platform).

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "tv/contact.hpp"
#include "tv/error.hpp"
#include "tv/mover.hpp"
#include "tv/world.hpp"

namespace {

using tv::ItemId;
using tv::Rect;
using tv::Vec2;
using tv::World;

constexpr double kTile = 16.0;

//        x 0                 64
//   y 64 +-------------------+   platform {0, 64, 64, 4}: answered `oneway`
//        +-------------------+
//   y 128 ===================    floor {0, 128, 64, 16}
struct Level {
  static constexpr Rect kPlatform{0, 64, 64, 4}, kFloor{0, 128, 64, 16};
  World world{16};
  ItemId platform = world.add(kPlatform);
  ItemId floor = world.add(kFloor);
  bool dropping = false;
  [[nodiscard]] tv::ResponseId answer(ItemId, ItemId other) const {
    if (other == platform) return dropping ? tv::response::cross : tv::response::oneway;
    return tv::response::slide;
  }
};

TEST(OneWayResponse, IsABuiltInOfTheTable) {
  EXPECT_EQ(tv::kBuiltinResponses[tv::response::oneway].name, "oneway");
  EXPECT_EQ(tv::builtinResponseId("oneway"), tv::response::oneway);
  World w;
  EXPECT_EQ(w.responseId("oneway"), tv::response::oneway);
  EXPECT_THROW((void)w.addResponse("oneway", &tv::slideResponse), tv::Error) << "a built-in name";
}

TEST(OneWayResponse, ABodyFallingFromAboveLandsExactlyOnTopAtOneToTenTilesAMoveWithEveryMover) {
  for (const std::string_view name : tv::moverNames()) {
    // The discrete movers teleport and push out of whatever they end in: see the last test.
    if (name == "discrete" || name == "substep-discrete") continue;
    for (int tiles = 1; tiles <= 10; ++tiles) {
      Level s;
      const auto filter = [&](ItemId a, ItemId b) { return s.answer(a, b); };
      // 0.37 px above it (3 px for the pixel mover, exact on whole pixels only).
      const double y0 = 64 - 8 - (name == "pixel" ? 3.0 : 0.37);
      const ItemId body = s.world.add({20, y0, 8, 8});
      tv::Mover mover(tv::parseMover(name));
      const tv::MoveResult r = mover.move(s.world, body, {20, y0 + tiles * kTile}, filter);
      EXPECT_EQ(s.world.rect(body).bottom(), 64.0) << name << " " << tiles;
      ASSERT_FALSE(r.collisions.empty()) << name << " " << tiles;
      EXPECT_EQ(r.collisions.back().response, tv::response::oneway);
      const tv::Collision& c = r.collisions.back();
      EXPECT_EQ(tv::velocityAfter({0, 5}, c), (Vec2{0, 0}))
          << name << " " << tiles << " landed: overlaps " << c.overlaps << " normal " << c.normal.x
          << "," << c.normal.y << " bottom " << c.itemRect.bottom();
    }
  }
}

TEST(OneWayResponse, ABodyJumpingUpThroughItIsNeverSnaggedAndKeepsItsVelocity) {
  // From under the platform, 2 to 10 tiles a move, with every mover but the discrete ones.
  for (const std::string_view name : tv::moverNames()) {
    if (name == "discrete" || name == "substep-discrete") continue;
    for (int tiles = 2; tiles <= 10; ++tiles) {
      Level s;
      const auto filter = [&](ItemId a, ItemId b) { return s.answer(a, b); };
      const ItemId body = s.world.add({20, 120, 8, 8});
      const Vec2 goal{20, 120 - tiles * kTile};
      tv::Mover mover(tv::parseMover(name));
      const tv::MoveResult r = mover.move(s.world, body, goal, filter);
      EXPECT_EQ(r.position, goal) << name << " " << tiles;
      if (goal.y < 68) {
        ASSERT_FALSE(r.collisions.empty()) << name << " " << tiles;
        EXPECT_EQ(r.collisions[0].normal, (Vec2{0, 1})) << "met from below";
        EXPECT_EQ(tv::velocityAfter({0, -5}, r.collisions[0]), (Vec2{0, -5})) << "kept";
      }
    }
  }
}

TEST(OneWayResponse, NegativeControlAnsweredSlideTheJumpStopsUnderThePlatform) {
  Level s;
  const ItemId body = s.world.add({20, 120, 8, 8});
  const tv::MoveResult r = s.world.move(body, {20, 20});  // everything slides
  EXPECT_EQ(r.position, (Vec2{20, 68})) << "snagged under it";
}

TEST(OneWayResponse, ABodyInsideOrBesideItPassesAndOneEntirelyAboveByAnyMarginIsHeld) {
  //   inside: {20, 62, 8, 8} overlaps the platform's top 2 px: falls through it.
  Level s;
  const auto filter = [&](ItemId a, ItemId b) { return s.answer(a, b); };
  const ItemId inside = s.world.add({20, 62, 8, 8});
  EXPECT_EQ(s.world.move(inside, {20, 100}, filter).position, (Vec2{20, 100}));
  // beside: {-8, 64, 8, 8}, level with the platform, walks into its side: passes.
  const ItemId beside = s.world.add({-8, 64, 8, 8});
  EXPECT_EQ(s.world.move(beside, {30, 64}, filter).position, (Vec2{30, 64}));
  // Above by the smallest step a double has: held.
  const double y = std::nextafter(64.0 - 8, 0.0);
  const ItemId hair = s.world.add({40, y, 8, 8});
  ASSERT_LT(s.world.rect(hair).bottom(), 64.0);
  EXPECT_EQ(s.world.move(hair, {40, 90}, filter).position.y, 56.0);
}

TEST(OneWayResponse, NegativeControlTheWithin1pxTestLandsABodyThatWasInsideThePlatform) {
  // Some games hold a body on a one-way platform when its bottom was "within 1 px" of the top
  // (a margin against rounding): a body 0.5 px inside the platform is then pulled up onto it.
  Level s;
  const ItemId body = s.world.add({20, 56.5, 8, 8});  // bottom 64.5: inside by 0.5
  const auto within1px = [&](ItemId a, ItemId b) {
    if (b != s.platform) return tv::response::slide;
    return s.world.rect(a).bottom() <= s.world.rect(b).y + 1 ? tv::response::slide
                                                             : tv::response::cross;
  };
  const tv::MoveResult naive = s.world.check(body, {20, 90}, within1px);
  EXPECT_NE(naive.position, (Vec2{20, 90})) << "held by a platform it was inside";
  const auto filter = [&](ItemId a, ItemId b) { return s.answer(a, b); };
  EXPECT_EQ(s.world.move(body, {20, 90}, filter).position, (Vec2{20, 90})) << "oneway: passes";
}

TEST(OneWayResponse, ADropThroughIsTheFilterAnsweringCrossForThePlatform) {
  Level s;
  const auto filter = [&](ItemId a, ItemId b) { return s.answer(a, b); };
  const ItemId body = s.world.add({20, 56, 8, 8});  // standing on it
  EXPECT_EQ(s.world.move(body, {20, 70}, filter).position, (Vec2{20, 56})) << "held";
  s.dropping = true;  // the player pressed down
  EXPECT_EQ(s.world.move(body, {20, 62}, filter).position, (Vec2{20, 62}));
  s.dropping = false;  // released while inside the platform: it goes on falling
  EXPECT_EQ(s.world.move(body, {20, 100}, filter).position, (Vec2{20, 100}));
}

TEST(OneWayResponse, BumpsRulesGiveTheSame) {
  Level s;
  const auto filter = [&](ItemId a, ItemId b) { return s.answer(a, b); };
  tv::MoveOptions bump;
  bump.semantics = tv::MoveSemantics::bump;
  const ItemId faller = s.world.add({20, 30, 8, 8});
  EXPECT_EQ(s.world.move(faller, {20, 90}, filter, bump).position, (Vec2{20, 56}));
  const ItemId jumper = s.world.add({40, 120, 8, 8});
  EXPECT_EQ(s.world.move(jumper, {40, 20}, filter, bump).position, (Vec2{40, 20}));
}

TEST(OneWayResponse, TheGroundUnderABodyAnsweredOnewayIsAOneWayPlatform) {
  Level s;
  const auto filter = [&](ItemId a, ItemId b) { return s.answer(a, b); };
  const ItemId body = s.world.add({20, 56, 8, 8});
  tv::Contacts contacts;
  tv::ContactOptions o;
  o.filter = filter;
  contacts.update(s.world, body, o);
  EXPECT_EQ(contacts.ground(body).kind, tv::GroundKind::oneWay);
  EXPECT_EQ(contacts.ground(body).item, s.platform);
}

TEST(OneWayResponse, AOneWayPlatformOfNoHeightIsRefusedNamingIt) {
  // A one-way side on a zero-size edge: the world holds only rects with an interior.
  World w(16);
  try {
    (void)w.add({0, 64, 64, 0});
    FAIL() << "a platform of height 0 was added";
  } catch (const tv::Error& e) {
    EXPECT_NE(std::string(e.what()).find("h"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)w.add({0, 1e17, 64, 1}), tv::Error) << "a height that rounds away";
  EXPECT_EQ(w.count(), 0u);
}

TEST(OneWayResponse, TheDiscreteMoverTeleportsAndIsPushedOutThroughIt) {
  // The naive mover (kept as a negative control) teleports into the platform and is pushed
  // out along its shallowest axis, whatever the response: at 2 tiles a move it ends below it.
  Level s;
  const auto filter = [&](ItemId a, ItemId b) { return s.answer(a, b); };
  const ItemId body = s.world.add({20, 50, 8, 8});
  tv::Mover discrete(tv::parseMover("discrete"));
  const tv::MoveResult r = discrete.move(s.world, body, {20, 50 + 2 * kTile}, filter);
  EXPECT_GT(r.position.y, 64.0) << "fell through the one-way platform";
}

}  // namespace
