// Specification of errors at the API boundary (tv/error.hpp): every bad input throws tv::Error
// whose message names the argument and echoes its value, and the world is left as it was
// (stateHash() bit for bit).

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <limits>
#include <string>
#include <string_view>

#include "expect_rejected.hpp"
#include "tv/error.hpp"
#include "tv/mover.hpp"
#include "tv/world.hpp"

namespace {

using tv::ItemId;
using tv::Rect;
using tv::Vec2;
using tv::World;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// A small world with one item in it and one removed.
struct Scene {
  World world{16};
  ItemId wall = world.add({20, -50, 10, 100});
  ItemId mover = world.add({0, 0, 10, 10});
  ItemId removed = [this] {
    const ItemId id = world.add({100, 100, 4, 4});
    world.remove(id);
    return id;
  }();
};

// [SECTION] the message format ------------------------------------------------------------------

TEST(FormatNumber, IsTheShortestTextThatReadsBack) {
  EXPECT_EQ(tv::formatNumber(8.1), "8.1");
  EXPECT_EQ(tv::formatNumber(-1.0), "-1");
  EXPECT_EQ(tv::formatNumber(0.0), "0");
  EXPECT_EQ(tv::formatNumber(kNaN), "nan");
  EXPECT_EQ(tv::formatNumber(kInf), "inf");
  EXPECT_EQ(tv::formatNumber(-kInf), "-inf");
  EXPECT_EQ(tv::formatNumber(1e300), "1e+300");
  EXPECT_EQ(std::stod(tv::formatNumber(0.1 + 0.2)), 0.1 + 0.2);
}

TEST(BadInput, MessagesNameTheCallTheArgumentAndTheValue) {
  Scene s;
  try {
    (void)s.world.add({0, 0, -1, 5});
    FAIL() << "expected tv::Error";
  } catch (const tv::Error& e) {
    EXPECT_STREQ(e.what(), "tv::World::add: w must be finite and > 0, but was -1");
  }
}

// [SECTION] cell size ---------------------------------------------------------------------------

TEST(BadInput, CellSizeMustBeFiniteAndPositive) {
  for (const double bad : {0.0, -0.0, -16.0, kNaN, kInf, -kInf}) {
    try {
      const World w(bad);
      ADD_FAILURE() << "World(" << bad << ") did not throw";
    } catch (const tv::Error& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find("cellSize"), std::string::npos) << msg;
      EXPECT_NE(msg.find(tv::formatNumber(bad)), std::string::npos) << msg;
    }
  }
}

// [SECTION] rects -------------------------------------------------------------------------------

TEST(BadInput, AddRejectsNonFiniteCoordinates) {
  Scene s;
  expectRejected(s.world, {"tv::World::add", "x must", "nan"}, [&] {
    (void)s.world.add({kNaN, 0, 1, 1});
  });
  expectRejected(s.world, {"y must", "inf"}, [&] { (void)s.world.add({0, kInf, 1, 1}); });
  expectRejected(s.world, {"x must", "-inf"}, [&] { (void)s.world.add({-kInf, 0, 1, 1}); });
}

TEST(BadInput, AddRejectsZeroNegativeAndNonFiniteSizes) {
  Scene s;
  expectRejected(s.world, {"w must", "was 0"}, [&] { (void)s.world.add({0, 0, 0, 1}); });
  expectRejected(s.world, {"h must", "-2.5"}, [&] { (void)s.world.add({0, 0, 1, -2.5}); });
  expectRejected(s.world, {"w must", "nan"}, [&] { (void)s.world.add({0, 0, kNaN, 1}); });
  expectRejected(s.world, {"h must", "inf"}, [&] { (void)s.world.add({0, 0, 1, kInf}); });
  expectRejected(s.world, {"w must", "-0"}, [&] { (void)s.world.add({0, 0, -0.0, 1}); });
}

TEST(BadInput, AddRejectsCoordinatesTooFarForTheCellSize) {
  Scene s;
  expectRejected(s.world, {"x=1e+300", "too far", "cell size 16"}, [&] {
    (void)s.world.add({1e300, 0, 1, 1});
  });
  // Finite corner, infinite far edge.
  expectRejected(s.world, {"x=1.7e+308", "w=1e+308"}, [&] {
    (void)s.world.add({1.7e308, 0, 1e308, 1});
  });
  // Fine for cells of 16, too many cells of a micrometre: 1e10 / 1e-6 = 1e16 > 2^52.
  World fine(1e-6);
  expectRejected(fine, {"y=1e+10", "cell size 1e-06"}, [&] { (void)fine.add({0, 1e10, 1, 1}); });
}

TEST(BadInput, UpdateRejectsBadRectsAndPositions) {
  Scene s;
  expectRejected(s.world, {"tv::World::update", "h must", "-1"}, [&] {
    s.world.update(s.mover, Rect{0, 0, 10, -1});
  });
  expectRejected(s.world, {"x must", "nan"}, [&] { s.world.update(s.mover, Vec2{kNaN, 0}); });
  expectRejected(s.world, {"y=-1e+300", "too far"}, [&] {
    s.world.update(s.mover, Vec2{0, -1e300});
  });
  EXPECT_EQ(s.world.rect(s.mover), (Rect{0, 0, 10, 10}));
}

// [SECTION] unknown and removed items -------------------------------------------------------------

TEST(BadInput, RemovedItemsAreRejectedByEveryCall) {
  Scene s;
  World& w = s.world;
  const ItemId r = s.removed;  // {index=2, generation=0}, now generation 1 in the world
  const std::initializer_list<std::string_view> names = {"index=2", "generation=0",
                                                         "not in the world"};
  expectRejected(w, names, [&] { w.remove(r); });
  expectRejected(w, names, [&] { (void)w.rect(r); });
  expectRejected(w, names, [&] { (void)w.order(r); });
  expectRejected(w, names, [&] { w.update(r, Vec2{1, 1}); });
  expectRejected(w, names, [&] { w.update(r, Rect{1, 1, 2, 2}); });
  expectRejected(w, names, [&] { (void)w.move(r, {5, 5}); });
  expectRejected(w, names, [&] { (void)w.check(r, {5, 5}); });
}

TEST(BadInput, NeverAddedAndDefaultHandlesAreRejected) {
  Scene s;
  World& w = s.world;
  expectRejected(w, {"index=41", "not in the world"}, [&] { (void)w.rect(ItemId{41, 0}); });
  expectRejected(w, {"index=4294967295"}, [&] { (void)w.move(ItemId{}, {0, 0}); });
  expectRejected(w, {"generation=1"}, [&] {
    w.remove(ItemId{s.mover.index, s.mover.generation + 1});
  });
}

// [SECTION] moves ---------------------------------------------------------------------------------

TEST(BadInput, MoveRejectsNonFiniteGoals) {
  Scene s;
  World& w = s.world;
  expectRejected(w, {"tv::World::move", "goal.x", "nan"}, [&] {
    (void)w.move(s.mover, {kNaN, 0});
  });
  expectRejected(w, {"goal.y", "-inf"}, [&] { (void)w.move(s.mover, {0, -kInf}); });
  expectRejected(w, {"tv::World::check", "goal.x"}, [&] { (void)w.check(s.mover, {kInf, 0}); });
  expectRejected(w, {"tv::World::project", "goal.y", "nan"}, [&] {
    (void)w.project({0, 0, 1, 1}, {0, kNaN});
  });
}

TEST(BadInput, MoveRejectsGoalsTooFarForTheCellSize) {
  Scene s;
  expectRejected(s.world, {"goal {1e+300, 0}", "too far", "cell size 16"}, [&] {
    (void)s.world.move(s.mover, {1e300, 0});
  });
  // The goal itself is finite, the goal rect's far edge is not.
  expectRejected(s.world, {"goal {0, 1.7976931348623157e+308}"}, [&] {
    (void)s.world.move(s.mover, {0, 1.7976931348623157e308});
  });
}

TEST(BadInput, MaxResponsesMustBeInRange) {
  Scene s;
  for (const int bad : {0, -1, 4097, 1 << 30}) {
    tv::MoveOptions o;
    o.maxResponses = bad;
    expectRejected(s.world, {"maxResponses", "[1, 4096]", std::to_string(bad)}, [&] {
      (void)s.world.move(s.mover, {30, 0}, {}, o);
    });
  }
  // The bounds themselves are fine.
  tv::MoveOptions o;
  o.maxResponses = 1;
  EXPECT_NO_THROW((void)s.world.check(s.mover, {30, 0}, {}, o));
  o.maxResponses = 4096;
  EXPECT_NO_THROW((void)s.world.check(s.mover, {30, 0}, {}, o));
}

TEST(BadInput, ProjectRejectsBadRects) {
  Scene s;
  expectRejected(s.world, {"tv::World::project", "w must", "was 0"}, [&] {
    (void)s.world.project({0, 0, 0, 1}, {5, 5});
  });
}

// [SECTION] responses -----------------------------------------------------------------------------

TEST(BadInput, ResponseNamesMustBeUniqueAndNonEmpty) {
  Scene s;
  World& w = s.world;
  expectRejected(w, {"tv::World::addResponse", "'slide'", "already"},
                 [&] { (void)w.addResponse("slide", &tv::touchResponse); });
  (void)w.addResponse("stick", &tv::touchResponse);
  expectRejected(w, {"'stick'"}, [&] { (void)w.addResponse("stick", &tv::slideResponse); });
  expectRejected(w, {"name", "empty"}, [&] { (void)w.addResponse("", &tv::touchResponse); });
  expectRejected(w, {"'nothing'"}, [&] { (void)w.addResponse("nothing", nullptr); });
}

TEST(BadInput, UnknownResponsesAreRejectedByName) {
  Scene s;
  expectRejected(s.world, {"'glue'"}, [&] { (void)s.world.responseId("glue"); });
  expectRejected(s.world, {"99"}, [&] { (void)s.world.responseName(99); });
}

// [SECTION] queries -------------------------------------------------------------------------------

TEST(BadInput, QueryRectRejectsBadRects) {
  Scene s;
  expectRejected(s.world, {"tv::World::queryRect", "x must", "nan"}, [&] {
    (void)s.world.queryRect({kNaN, 0, 1, 1});
  });
  expectRejected(s.world, {"w", "-1"}, [&] { (void)s.world.queryRect({0, 0, -1, 1}); });
  expectRejected(s.world, {"h must", "inf"}, [&] { (void)s.world.queryRect({0, 0, 1, kInf}); });
  expectRejected(s.world, {"y=1e+300", "too far"}, [&] {
    (void)s.world.queryRect({0, 1e300, 1, 1});
  });
}

TEST(BadInput, QueryPointAndSegmentRejectNonFiniteValues) {
  Scene s;
  expectRejected(s.world, {"tv::World::queryPoint", "y must", "nan"}, [&] {
    (void)s.world.queryPoint({0, kNaN});
  });
  expectRejected(s.world, {"tv::World::querySegment", "b.y", "inf"}, [&] {
    (void)s.world.querySegment({0, 0}, {5, kInf});
  });
  expectRejected(s.world, {"a.x", "-inf"}, [&] { (void)s.world.querySegment({-kInf, 0}, {5, 5}); });
}

// A point or segment too far from the origin for the grid is named with its value.
TEST(BadInput, QueryPointAndSegmentTooFarEchoTheValue) {
  Scene s;
  expectRejected(s.world, {"tv::World::queryPoint", "1e+300"}, [&] {
    (void)s.world.queryPoint({1e300, 0});
  });
  expectRejected(s.world, {"tv::World::querySegment", "-1e+300"}, [&] {
    (void)s.world.querySegment({0, 0}, {0, -1e300});
  });
}

TEST(BadInput, AnyOverlapRejectsBadRects) {
  Scene s;
  expectRejected(s.world, {"tv::World::anyOverlap", "w=nan"}, [&] {
    (void)s.world.anyOverlap({0, 0, kNaN, 1});
  });
  expectRejected(s.world, {"x=1e+300"}, [&] { (void)s.world.anyOverlap({1e300, 0, 1, 1}); });
}


// [SECTION] inputs that were accepted and then went wrong ------------------------------------------

// toCell cast a NaN or a 1e300 · (1 / size) to an integer: undefined behaviour. Refused by name.
TEST(BadInput, ToCellRejectsNonFiniteAndFarPoints) {
  Scene s;
  expectRejected(s.world, {"tv::World::toCell", "x must", "nan"},
                 [&] { (void)s.world.toCell({kNaN, 0}); });
  expectRejected(s.world, {"tv::World::toCell", "1e+300", "too far"},
                 [&] { (void)s.world.toCell({1e300, 0}); });
  EXPECT_EQ(s.world.toCell({-0.5, 33}), (tv::Cell{-1, 2}));
}

// queryRect refused a negative size; anyOverlap, the same question, answered it.
TEST(BadInput, AnyOverlapRejectsNegativeSizesLikeQueryRect) {
  Scene s;
  expectRejected(s.world, {"tv::World::anyOverlap", "w=-1", "negative size"},
                 [&] { (void)s.world.anyOverlap({0, 0, -1, 1}); });
  expectRejected(s.world, {"h=-2"}, [&] { (void)s.world.anyOverlap({0, 0, 1, -2}); });
  EXPECT_TRUE(s.world.anyOverlap({25, 0, 0, 0})) << "a zero-size probe is a point: allowed";
}

// idAt(999) threw std::out_of_range, which a caller catching tv::Error does not catch.
TEST(BadInput, IdAtRejectsASlotThatHoldsNoItemWithATvError) {
  Scene s;
  expectRejected(s.world, {"tv::World::idAt", "slot 999", "holds no item"},
                 [&] { (void)s.world.idAt(999); });
  expectRejected(s.world, {"slot " + std::to_string(s.removed.index)},
                 [&] { (void)s.world.idAt(s.removed.index); });
  EXPECT_EQ(s.world.idAt(s.wall.index), s.wall);
}

// A MoverSpec whose kind was cast from an integer that names no mover moved nothing and
// reported (0, 0).
TEST(BadInput, AMoverKindThatNamesNoMoverIsRejected) {
  tv::MoverSpec spec;
  spec.kind = static_cast<tv::MoverKind>(17);
  try {
    const tv::Mover m(spec);
    ADD_FAILURE() << "kind 17 was accepted";
  } catch (const tv::Error& e) {
    EXPECT_STREQ(e.what(), "tv::Mover: kind must be a MoverKind (0 to 6), but was 17");
  }
  spec.kind = tv::MoverKind::adaptive;  // the last one is fine
  EXPECT_NO_THROW((void)tv::Mover(spec));
}

// "ignore" is response::ignore's name (responseId("ignore")): a response registered under it
// would be unreachable by name.
TEST(BadInput, TheNameIgnoreIsReservedForResponseIgnore) {
  Scene s;
  expectRejected(s.world, {"tv::World::addResponse", "'ignore'", "reserved"},
                 [&] { (void)s.world.addResponse("ignore", &tv::touchResponse); });
  EXPECT_EQ(s.world.responseId("ignore"), tv::response::ignore);
  EXPECT_NO_THROW((void)s.world.addResponse("ignored", &tv::touchResponse));
}

// World(5e-324) was accepted, but 1 / 5e-324 is infinite and every rect was then refused.
TEST(BadInput, CellSizesOutsideTwoToTheMinus485AndTwoToThe500AreRejected) {
  for (const double bad : {5e-324, 1e-300, 0x1p-486, 0x1p501, 1e154, 1e307}) {
    try {
      const World w(bad);
      ADD_FAILURE() << "World(" << bad << ") did not throw";
    } catch (const tv::Error& e) {
      EXPECT_EQ(std::string(e.what()),
                "tv::World: cellSize must be in [2^-485, 2^500] (about 1e-146 to 3.27e150), "
                "but was " + tv::formatNumber(bad));
    }
  }
  for (const double good : {0x1p-485, 1e-100, 0.1, 64.0, 0x1p500}) {
    const World w(good);
    EXPECT_EQ(w.cellSize(), good);
  }
}

// w = 1e-30 at x = 1e9 is far below an ulp of x: right() == x, a rect with no interior that
// nothing can ever hit. Refused, naming both values.
TEST(BadInput, ARectWhoseSizeRoundsAwayHasNoInteriorAndIsRejected) {
  Scene s;
  expectRejected(s.world, {"tv::World::add", "w=1e-30", "x=1e+09", "no interior"},
                 [&] { (void)s.world.add({1e9, 0, 1e-30, 1}); });
  expectRejected(s.world, {"h=1e-30", "y=-1e+09"},
                 [&] { (void)s.world.add({0, -1e9, 1, 1e-30}); });
  expectRejected(s.world, {"tv::World::update", "w=5e-324"},
                 [&] { s.world.update(s.mover, Rect{100, 0, 5e-324, 32}); });
  // The same sizes at the origin have an interior: accepted.
  EXPECT_NO_THROW((void)s.world.add({0, 200, 1e-30, 1}));
  EXPECT_NO_THROW((void)s.world.add({1e9, 0, 1e-6, 1})) << "over half an ulp of 1e9 (6e-8)";
}

}  // namespace
