// A recording as the debugger's source: frames and calls, the traced item, clicking an item, and the
// trace shown for a call being the one core made while the replay re-ran it.
#include <gtest/gtest.h>

#include <algorithm>
#include <span>
#include <string_view>

#include "tv/record/recorder.hpp"
#include "tv/record/replay.hpp"
#include "tv/ui/palette.hpp"
#include "tv/ui/replay_source.hpp"

namespace tv::ui {
namespace {

// A small game, recorded: a floor of 16 px tiles, a thin ghost wall the player's filter
// passes through, a solid wall, and the player running right along the floor into it.
//
//      [p]-->   |g|      |wall|
//   ===================================   floor, y 32..48
//   0          40..42    64..80
struct Game {
  std::vector<std::uint8_t> bytes;
  ItemId player, ghost, wall, tile0;
  std::vector<MoveTrace> live;  // the game's own traces of the player's moves, per frame
  std::vector<Vec2> ends;       // where each of those moves ended
};

Game record(int frames) {
  Game g;
  World w(16);
  Recorder rec;
  w.attach(rec);
  g.tile0 = w.add({0, 32, 16, 16});
  for (int i = 1; i < 8; ++i) w.add({i * 16.0, 32, 16, 16});
  g.ghost = w.add({40, 0, 2, 32});
  g.wall = w.add({64, 0, 16, 32});
  g.player = w.add({0, 20, 8, 12});
  rec.label(g.player, "player", "player");
  rec.label(g.ghost, "ghost", "trigger");
  rec.label(g.wall, "wall", "solid");
  const auto filter = [&](ItemId, ItemId other) {
    return other == g.ghost ? response::ignore : response::slide;
  };
  for (int f = 0; f < frames; ++f) {
    // Run 6 px a frame, pressed into the floor by 1 px of gravity.
    const Vec2 goal = w.rect(g.player).position() + Vec2{6, 1};
    MoveTrace t;
    MoveOptions o;
    o.trace = &t;
    const MoveResult r = w.move(g.player, goal, filter, o);
    g.live.push_back(t);
    g.ends.push_back(r.position);
    (void)w.queryRect({0, 0, 100, 100});
    rec.frame();
  }
  w.detach();
  rec.close();
  g.bytes = rec.bytes();
  return g;
}

ReplaySource open(const Game& g) {
  return ReplaySource(Replay::fromBytes(g.bytes), "game.tvrec");
}

// The player's move in the frame on screen (frame 0 also holds the adds and labels).
std::uint32_t moveCall(const ReplaySource& s) {
  for (const CallInfo& c : s.calls()) {
    if (c.kind == CallKind::move) return c.index;
  }
  ADD_FAILURE() << "no move in frame " << s.frame();
  return 0;
}

TEST(ReplaySource, ShowsAFrameAsItEndedWithItsCallsListed) {
  const Game g = record(6);
  ReplaySource s = open(g);
  s.goTo(3);
  EXPECT_EQ(s.frame(), 3u);
  EXPECT_FALSE(s.call());
  ASSERT_EQ(s.calls().size(), 2u);  // the move, the query
  EXPECT_EQ(s.calls()[0].kind, CallKind::move);
  EXPECT_EQ(s.calls()[1].kind, CallKind::queryRect);
  EXPECT_EQ(s.world().rect(g.player).position(), g.ends[3]);
}

TEST(ReplaySource, GoingPastTheLastFrameShowsTheLast) {
  const Game g = record(4);
  ReplaySource s = open(g);
  s.goTo(1000);
  EXPECT_EQ(s.frame(), s.lastFrame());
}

TEST(ReplaySource, SelectingACallShowsTheWorldJustAfterItAndTracesItsItem) {
  const Game g = record(6);
  ReplaySource s = open(g);
  s.goTo(4);
  s.selectCall(moveCall(s));
  ASSERT_TRUE(s.call());
  EXPECT_EQ(s.traced(), g.player);  // the call's item is traced
  const MoveTrace* t = s.callTrace();
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->item, g.player);
  EXPECT_EQ(t->final, g.ends[4]);
  EXPECT_EQ(s.world().rect(g.player).position(), g.ends[4]);
  // The earlier moves trail behind, oldest first, each with its frame.
  ASSERT_GE(s.history().size(), 2u);
  EXPECT_EQ(s.history().back().tick, 4u);
  EXPECT_EQ(s.history()[s.history().size() - 2].tick, 3u);
}

// The debugger never recomputes a collision: what it shows is the trace core filled while the
// replay re-ran the call, which is the trace the game's own move made.
TEST(ReplaySource, ACallsTraceIsTheOneTheGamesMoveMade) {
  const Game g = record(12);
  ReplaySource s = open(g);
  for (std::uint64_t f = 0; f < 12; ++f) {
    s.goTo(f);
    s.selectCall(moveCall(s));
    const MoveTrace* t = s.callTrace();
    ASSERT_NE(t, nullptr) << "frame " << f;
    const MoveTrace& live = g.live[f];
    EXPECT_EQ(t->cells, live.cells) << "frame " << f;
    EXPECT_EQ(t->candidates, live.candidates) << "frame " << f;
    ASSERT_EQ(t->hits.size(), live.hits.size()) << "frame " << f;
    for (std::size_t h = 0; h < t->hits.size(); ++h) {
      EXPECT_EQ(t->hits[h].other, live.hits[h].other);
      EXPECT_EQ(t->hits[h].ti, live.hits[h].ti);
      EXPECT_EQ(t->hits[h].normal, live.hits[h].normal);
      EXPECT_EQ(t->hits[h].touch, live.hits[h].touch);
    }
  }
}

// The game's filter passed through the ghost wall; the replay cannot call it, so the answer it
// gave comes from the recording, and the trace shows it.
TEST(ReplaySource, TheTraceCarriesTheFiltersRecordedAnswers) {
  const Game g = record(12);
  ReplaySource s = open(g);
  bool sawGhostIgnored = false, sawWallSlide = false;
  for (std::uint64_t f = 0; f < 12; ++f) {
    s.goTo(f);
    s.selectCall(moveCall(s));
    ASSERT_NE(s.callTrace(), nullptr);
    for (const TraceAnswer& a : s.callTrace()->answers) {
      sawGhostIgnored |= a.other == g.ghost && a.response == response::ignore;
      sawWallSlide |= a.other == g.wall && a.response == response::slide;
    }
  }
  EXPECT_TRUE(sawGhostIgnored);
  EXPECT_TRUE(sawWallSlide);
  // And the player ended against the wall, not inside or past it (the ghost did not stop it).
  EXPECT_EQ(s.world().rect(g.player).right(), 64.0);
}

TEST(ReplaySource, AQueryCallHasNoMoveTrace) {
  const Game g = record(3);
  ReplaySource s = open(g);
  s.goTo(1);
  s.selectCall(1);
  EXPECT_EQ(s.callTrace(), nullptr);
  s.selectCall(7);  // out of range: ignored
  EXPECT_EQ(s.call(), std::optional<std::uint32_t>(1));
}

TEST(ReplaySource, ClickingPicksTheMovingItemBeforeTheTileBehindIt) {
  const Game g = record(2);
  ReplaySource s = open(g);
  s.goTo(0);
  const Rect p = s.world().rect(g.player);
  EXPECT_EQ(s.itemAt(p.center()), g.player);
  EXPECT_EQ(s.itemAt({8, 40}), g.tile0);
  EXPECT_FALSE(s.itemAt({200, -50}));
  EXPECT_TRUE(s.moves(g.player));
  EXPECT_FALSE(s.moves(g.wall));
}

TEST(ReplaySource, NamesItemsByTheirLabels) {
  const Game g = record(2);
  ReplaySource s = open(g);
  EXPECT_EQ(s.findLabel("player"), g.player);
  EXPECT_FALSE(s.findLabel("nobody"));
  EXPECT_EQ(s.describe(g.wall), "wall");
}

TEST(ReplaySource, TracingAnotherItemKeepsTheFrameAndCall) {
  const Game g = record(6);
  ReplaySource s = open(g);
  s.goTo(5);
  s.trace(g.player);
  EXPECT_EQ(s.frame(), 5u);
  ASSERT_FALSE(s.history().empty());
  EXPECT_EQ(s.history().back().tick, 5u);
  s.trace(g.wall);  // never moves: nothing to trace
  EXPECT_TRUE(s.history().empty());
  EXPECT_FALSE(s.divergence());
}

// Playing forward steps only the new frame's calls; it must show exactly what seeking to that
// frame shows (the same world, by state hash, and the same traced moves).
TEST(ReplaySource, PlayingForwardShowsWhatSeekingShows) {
  const Game g = record(30);
  ReplaySource played = open(g);
  played.trace(g.player);
  for (std::uint64_t f = 0; f < 30; ++f) {
    played.goTo(f);
    ReplaySource sought = open(g);
    sought.trace(g.player);
    sought.goTo(f);
    ASSERT_EQ(played.world().stateHash(), sought.world().stateHash()) << "frame " << f;
    ASSERT_EQ(played.history().size(), sought.history().size()) << "frame " << f;
    for (std::size_t k = 0; k < played.history().size(); ++k) {
      EXPECT_EQ(played.history()[k].tick, sought.history()[k].tick) << "frame " << f;
      EXPECT_EQ(played.history()[k].trace.final, sought.history()[k].trace.final);
    }
  }
}

// Items that never move: level geometry is drawn as solids, but an item the game said what it
// is (a guard that stands and shoots) is drawn as a body in its category's colour.
//
//   [g]          [p]-->        g: "guard 1", category Guardian, never moves
//   ================           tiles, category "tile" (most of what never moves): solids
TEST(ReplaySource, DrawsAnItemThatNeverMovesInItsCategorysColourUnlessItIsTheLevel) {
  World w(16);
  Recorder rec;
  w.attach(rec);
  for (int i = 0; i < 8; ++i) rec.label(w.add({i * 16.0, 32, 16, 16}), "tile", "tile");
  const ItemId guard = w.add({0, 16, 8, 16});
  rec.label(guard, "guard 1", "Guardian");
  const ItemId player = w.add({40, 20, 8, 12});
  rec.label(player, "player", "player");
  for (int f = 0; f < 3; ++f) {
    (void)w.move(player, w.rect(player).position() + Vec2{4, 0});
    rec.frame();
  }
  w.detach();
  rec.close();
  ReplaySource s(Replay::fromBytes(rec.bytes()), "game.tvrec");
  s.goTo(2);
  const WorldPicture p = s.picture();
  EXPECT_EQ(p.solids.size(), 8u);
  ASSERT_EQ(p.bodies.size(), 2u);
  ASSERT_EQ(p.bodyFills.size(), 2u);
  for (std::size_t i = 0; i < p.bodies.size(); ++i) {
    if (p.bodies[i].item == guard) {
      EXPECT_EQ(p.bodyFills[i], palette::categoryColour("Guardian"));
    } else {
      EXPECT_EQ(p.bodies[i].item, player);
      EXPECT_EQ(p.bodyFills[i], 0u);  // a moving body keeps the body colours
    }
  }
}

}  // namespace
}  // namespace tv::ui
