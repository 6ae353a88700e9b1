// tv::Batch (hull grid, event queue, paths re-based only by their own events) against the
// obvious all-pairs search of batch_reference.cpp: the same positions and the same collisions,
// bit for bit, in the same order, on random scenes and on scenes built to tie — and in any
// order of the moves.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "batch_reference.hpp"
#include "tv/batch.hpp"
#include "tv/sim/rng.hpp"

namespace tv {
namespace {

void expectSame(const Collision& a, const Collision& b, const std::string& where) {
  EXPECT_EQ(a.item, b.item) << where;
  EXPECT_EQ(a.other, b.other) << where;
  EXPECT_EQ(a.ti, b.ti) << where;
  EXPECT_EQ(a.move, b.move) << where;
  EXPECT_EQ(a.normal, b.normal) << where;
  EXPECT_EQ(a.touch, b.touch) << where;
  EXPECT_EQ(a.target, b.target) << where;
  EXPECT_EQ(a.itemRect, b.itemRect) << where;
  EXPECT_EQ(a.otherRect, b.otherRect) << where;
  EXPECT_EQ(a.response, b.response) << where;
  EXPECT_EQ(a.corner, b.corner) << where;
  EXPECT_EQ(a.overlaps, b.overlaps) << where;
}

struct Tally {
  std::size_t events = 0, pairEvents = 0, ties = 0, crossings = 0;
};

// Steps a copy of `w` through tv::Batch and another through the reference, with the moves in
// the order given, and expects the same outcome for every body and the same world after.
void expectSameStep(const World& w, const std::vector<BatchMove>& moves, Filter filter,
                    int maxEvents, const std::string& where, Tally* tally = nullptr) {
  World mine = w, theirs = w;
  Batch batch;
  batch.step(mine, moves, filter, maxEvents);
  std::vector<double> instants;
  const std::vector<reference::Outcome> ref =
      reference::batchStep(theirs, moves, filter, maxEvents, &instants);
  ASSERT_EQ(batch.size(), ref.size()) << where;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    const BatchOutcome out = batch.outcome(i);
    EXPECT_EQ(out.position, ref[i].position) << where << " body " << i;
    ASSERT_EQ(out.collisions.size(), ref[i].collisions.size()) << where << " body " << i;
    for (std::size_t k = 0; k < ref[i].collisions.size(); ++k) {
      expectSame(out.collisions[k], ref[i].collisions[k], where + " body " + std::to_string(i));
      if (!tally) continue;
      const Collision& c = out.collisions[k];
      ++tally->events;
      if (c.response == response::cross) ++tally->crossings;
      bool pair = false;
      for (const BatchMove& m : moves) pair = pair || m.item == c.other;
      if (pair) ++tally->pairEvents;
    }
  }
  // An event that ran at the very instant of the one before it: a tie the order had to break.
  if (tally)
    for (std::size_t e = 1; e < instants.size(); ++e) tally->ties += instants[e] == instants[e - 1];
  EXPECT_EQ(mine.stateHash(), theirs.stateHash()) << where;
}

struct Scene {
  World world{16};
  std::vector<BatchMove> moves;
};

// Movers and tiles on a grid of quarters (so that times tie exactly), some steps long enough
// to cross the whole scene, `offset` away from the origin (where positions along a path round).
Scene randomScene(std::uint64_t seed, int maxMovers, double offset) {
  sim::Rng rng{seed};
  const auto uniform = [&] { return rng.uniform(); };
  const auto grid = [&](double lo, double hi) {
    return lo + std::floor((hi - lo) * 4 * uniform()) / 4;
  };
  Scene s;
  const int tiles = static_cast<int>(rng.next() % 12);
  for (int k = 0; k < tiles; ++k)
    s.world.add({offset + grid(-64, 64), offset + grid(-64, 64), 8, 8});
  const int movers = 2 + static_cast<int>(rng.next() % static_cast<std::uint64_t>(maxMovers));
  const double speed = seed % 3 == 0 ? 64 : 24;
  for (int k = 0; k < movers; ++k) {
    const Rect r{offset + grid(-64, 64), offset + grid(-64, 64), grid(1, 8) + 0.25, 4};
    if (s.world.anyOverlap(r)) continue;
    s.moves.push_back({s.world.add(r), {r.x + grid(-speed, speed), r.y + grid(-speed, speed)}});
  }
  return s;
}

// Every built-in response, and a filter under which some pairs ignore each other (one side
// only, or both).
const ResponseId kResponses[] = {response::touch, response::slide, response::bounce,
                                 response::cross};

TEST(BatchReference, MatchesTheAllPairsSearchBitForBitOnRandomScenes) {
  Tally tally;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    for (const double offset : {0.0, 1e6 + 0.375}) {
      const Scene s = randomScene(seed, 40, offset);
      for (const ResponseId resp : kResponses) {
        const auto filter = [resp](ItemId a, ItemId b) {
          return (a.index + 2 * b.index) % 7 == 0 ? response::ignore : resp;
        };
        expectSameStep(s.world, s.moves, filter, 4096,
                       "seed " + std::to_string(seed) + " offset " + std::to_string(offset) +
                           " response " + std::to_string(resp),
                       &tally);
        if (HasFatalFailure()) return;
      }
    }
  }
  // Preconditions: the scenes collide, bodies meet bodies, events tie and pairs cross.
  EXPECT_GT(tally.events, 2000u);
  EXPECT_GT(tally.pairEvents, 1000u);
  EXPECT_GT(tally.ties, 30u);
  EXPECT_GT(tally.crossings, 500u);
}

// The order of `moves` is not an input: every permutation gives every item the same outcome.
TEST(BatchReference, AnyOrderOfTheMovesGivesTheSameOutcome) {
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const Scene s = randomScene(seed * 7919, 30, 0.0);
    for (const ResponseId resp : kResponses) {
      World first = s.world;
      Batch batch;
      batch.step(first, s.moves, Filter::all(resp));
      std::vector<BatchMove> moves = s.moves;
      sim::Rng rng{seed};
      for (int round = 0; round < 4; ++round) {
        for (std::size_t i = moves.size(); i > 1; --i)  // Fisher–Yates
          std::swap(moves[i - 1], moves[rng.next() % i]);
        const std::string where = "seed " + std::to_string(seed) + " round " + std::to_string(round);
        expectSameStep(s.world, moves, Filter::all(resp), 4096, where);
        World shuffled = s.world;
        Batch other;
        other.step(shuffled, moves, Filter::all(resp));
        EXPECT_EQ(shuffled.stateHash(), first.stateHash()) << where;
        for (std::size_t i = 0; i < moves.size(); ++i) {
          const auto k = static_cast<std::size_t>(
              std::find_if(s.moves.begin(), s.moves.end(),
                           [&](const BatchMove& m) { return m.item == moves[i].item; }) -
              s.moves.begin());
          ASSERT_EQ(other.outcome(i).collisions.size(), batch.outcome(k).collisions.size()) << where;
          for (std::size_t c = 0; c < other.outcome(i).collisions.size(); ++c)
            expectSame(other.outcome(i).collisions[c], batch.outcome(k).collisions[c], where);
        }
      }
    }
  }
}

// Scenes built so that several events share an instant:
//
//   symmetric head-on pairs          a chain struck at one end       a cross of four
//   [a]-->  <--[b]                   [a]--> [b][c][d][e]              [n]
//   [c]-->  <--[d]  (same instant)   (each contact at one instant)     v
//                                                                 [w]->   <-[e]
//                                                                      ^
//                                                                     [s]
// with walls of tiles at exact distances, so that static hits tie with pair hits too; and a body
// that reaches a wall at the instant another lands on it (t = 1/2: a's right edge 8 -> 24 meets
// the wall at 16, b's bottom -12 -> 12 meets a's top at 0):
//
//        [b]
//         v
//   [a] ---> |wall|

TEST(BatchReference, MatchesOnScenesWhereEventsShareAnInstant) {
  Tally tally;
  for (const ResponseId resp : kResponses) {
    for (const double offset : {0.0, 4096.5}) {
      const std::string where = "response " + std::to_string(resp) + " offset " +
                                std::to_string(offset);
      {  // rows of symmetric head-on pairs, between two walls
        World w(16);
        std::vector<BatchMove> moves;
        for (int row = 0; row < 6; ++row) {
          const double y = offset + row * 10.0;
          const ItemId a = w.add({offset, y, 8, 8});
          const ItemId b = w.add({offset + 40, y, 8, 8});
          moves.push_back({a, {offset + 40, y}});
          moves.push_back({b, {offset, y}});
        }
        w.add({offset - 8, offset, 8, 60});
        w.add({offset + 48, offset, 8, 60});
        expectSameStep(w, moves, Filter::all(resp), 4096, where + " head-on", &tally);
      }
      {  // a chain at rest struck by one body, with a wall at its far end
        World w(16);
        std::vector<BatchMove> moves;
        const ItemId striker = w.add({offset, offset, 8, 8});
        moves.push_back({striker, {offset + 64, offset}});
        for (int k = 0; k < 5; ++k) {
          const ItemId link = w.add({offset + 16 + 8 * k, offset, 8, 8});
          moves.push_back({link, {offset + 16 + 8 * k, offset}});
        }
        w.add({offset + 56, offset - 8, 8, 24});
        expectSameStep(w, moves, Filter::all(resp), 4096, where + " chain", &tally);
      }
      {  // four bodies converging on one point at the same instant
        World w(16);
        const double c = offset + 32;
        const ItemId n = w.add({c, c - 24, 4, 4}), s = w.add({c, c + 24, 4, 4});
        const ItemId west = w.add({c - 24, c, 4, 4}), east = w.add({c + 24, c, 4, 4});
        const std::vector<BatchMove> moves = {
            {n, {c, c + 24}}, {s, {c, c - 24}}, {west, {c + 24, c}}, {east, {c - 24, c}}};
        expectSameStep(w, moves, Filter::all(resp), 4096, where + " cross", &tally);
      }
      {  // a wall hit and a landing at one instant, in rows whose walls move the tie around
        World w(16);
        std::vector<BatchMove> moves;
        for (int row = 0; row < 4; ++row) {
          const double y = offset + 40.0 * row;
          const ItemId a = w.add({offset, y, 8, 8});
          const ItemId b = w.add({offset + 2 + row, y - 20, 4, 8});
          w.add({offset + 16 + 8 * (row % 2), y - 4, 8, 16});
          moves.push_back({a, {offset + 16, y}});
          moves.push_back({b, {offset + 2 + row + 4 * (row % 3), y + 4}});
        }
        expectSameStep(w, moves, Filter::all(resp), 4096, where + " wall and landing", &tally);
      }
    }
  }
  EXPECT_GT(tally.pairEvents, 50u);
  EXPECT_GT(tally.ties, 20u);
}

// Cut short by maxEvents, both stop every body at the last event's instant.
TEST(BatchReference, MatchesWhenMaxEventsCutsTheTickShort) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Scene s = randomScene(seed, 30, 0.0);
    for (const int maxEvents : {1, 2, 3, 5, 8}) {
      expectSameStep(s.world, s.moves, Filter::all(response::bounce), maxEvents,
                     "seed " + std::to_string(seed) + " maxEvents " + std::to_string(maxEvents));
    }
  }
}

// A crowd large enough that the hull grid has many cells, with bounces that send bodies out of
// the hulls they were registered with.
TEST(BatchReference, MatchesOnACrowdWhoseBouncesLeaveTheirHulls) {
  sim::Rng rng{42};
  const auto uniform = [&] { return rng.uniform(); };
  World w(16);
  for (int k = 0; k < 40; ++k) w.add({std::floor(uniform() * 50) * 8, std::floor(uniform() * 50) * 8, 8, 8});
  std::vector<BatchMove> moves;
  while (moves.size() < 250) {
    const Rect r{uniform() * 400, uniform() * 400, 3 + uniform() * 4, 3 + uniform() * 4};
    if (w.anyOverlap(r)) continue;
    const double reach = moves.size() % 10 == 0 ? 120 : 12;  // a few fast ones
    moves.push_back({w.add(r), {r.x + (uniform() - 0.5) * reach, r.y + (uniform() - 0.5) * reach}});
  }
  for (const ResponseId resp : kResponses)
    expectSameStep(w, moves, Filter::all(resp), 4096, "response " + std::to_string(resp));
}

}  // namespace
}  // namespace tv
