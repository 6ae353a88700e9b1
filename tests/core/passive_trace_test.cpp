// Specification of "the trace is a passive observer": a move made with a MoveTrace is the move
// made without one, bit for bit, down to the pairs the filter is asked about and their order —
// and so is the same move made on a world rebuilt from the first one's state (as a replay seeks
// to a keyframe), whose cells list their items in another order.
//
// The level is shaped like the real game in which this once failed (smoky_level.hpp): a player
// sliding on blocks among a hundred puffs of smoke its filter ignores, debris and grenades
// bouncing in several cells, 64 px cells.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include "smoky_level.hpp"
#include "tv/trace.hpp"
#include "tv/world.hpp"

namespace tv {
namespace {

bool same(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
bool same(Vec2 a, Vec2 b) {
  return same(a.x, b.x) && same(a.y, b.y);
}
bool same(const Rect& a, const Rect& b) {
  return same(a.x, b.x) && same(a.y, b.y) && same(a.w, b.w) && same(a.h, b.h);
}
bool same(const Collision& x, const Collision& y) {
  return x.item == y.item && x.other == y.other && x.overlaps == y.overlaps &&
         x.corner == y.corner && same(x.ti, y.ti) && same(x.move, y.move) &&
         same(x.normal, y.normal) && same(x.touch, y.touch) && same(x.itemRect, y.itemRect) &&
         same(x.otherRect, y.otherRect) && x.response == y.response && same(x.target, y.target);
}

struct Asked {
  ItemId item, other;
  bool operator==(const Asked&) const = default;
};

// One move as a caller saw it: where it ended, what it hit, what the filter was asked.
struct Seen {
  Vec2 position;
  std::vector<Collision> collisions;
  std::vector<Asked> asked;
};

Seen makeMove(World& w, ItemId id, Vec2 goal, const Filter& f, MoveTrace* trace) {
  Seen s;
  const auto asking = [&](ItemId a, ItemId b) {
    s.asked.push_back({a, b});
    return f(a, b);
  };
  MoveOptions o;
  o.trace = trace;
  const MoveResult r = w.move(id, goal, Filter(asking), o);
  s.position = r.position;
  s.collisions.assign(r.collisions.begin(), r.collisions.end());
  return s;
}

// What differs between two makings of one move (empty when nothing does).
struct Tally {
  int moves = 0, asked = 0, unasked = 0, position = 0, collisions = 0;
  [[nodiscard]] int any() const { return asked + position + collisions; }
  void compare(const Seen& game, const Seen& other) {
    ++moves;
    if (game.asked != other.asked) ++asked;
    // A pair the game was never asked about: a recording has no answer for it.
    for (const Asked& a : other.asked) {
      if (std::find(game.asked.begin(), game.asked.end(), a) == game.asked.end()) {
        ++unasked;
        break;
      }
    }
    if (!same(game.position, other.position)) ++position;
    bool cols = game.collisions.size() != other.collisions.size();
    for (std::size_t k = 0; !cols && k < game.collisions.size(); ++k)
      cols = !same(game.collisions[k], other.collisions[k]);
    if (cols) ++collisions;
  }
  [[nodiscard]] std::string report() const {
    return std::to_string(any()) + " differences in " + std::to_string(moves) + " moves: " +
           std::to_string(asked) + " asked other pairs (" + std::to_string(unasked) +
           " a pair the game was never asked about), " + std::to_string(position) +
           " ended elsewhere, " + std::to_string(collisions) + " reported other collisions";
  }
};

// The game plays on `game` untraced; each of its moves is made again, traced, on a copy of the
// world as it was just before (same cells, same order in each) and on a world restored from its
// state (as a replay's keyframe), and compared.
struct Twins {
  World game{test::SmokyLevel::kCell};
  Tally copied, restored;
  MoveTrace trace;
  std::vector<Collision> collisions;  // the game's last move's, handed back to the level

  test::Calls calls() {
    test::Calls c;
    c.add = [this](const Rect& r) { return game.add(r); };
    c.remove = [this](ItemId id) { game.remove(id); };
    c.update = [this](ItemId id, const Rect& r) { game.update(id, r); };
    c.move = [this](ItemId id, Vec2 goal, Filter f) {
      World copy = game;
      World keyframe(game.cellSize());
      keyframe.restore(game.state());
      const Seen played = makeMove(game, id, goal, f, nullptr);
      trace.clear();
      copied.compare(played, makeMove(copy, id, goal, f, &trace));
      trace.clear();
      restored.compare(played, makeMove(keyframe, id, goal, f, &trace));
      collisions = played.collisions;
      return MoveResult{played.position, collisions};
    };
    return c;
  }
};

TEST(PassiveTrace, AMoveMadeWithATraceIsTheMoveMadeWithoutOneInASmokyLevel) {
  Twins t;
  test::SmokyLevel level(19);
  test::Calls calls = t.calls();
  level.build(calls);
  for (int frame = 0; frame < 1200; ++frame) level.frame(calls);
  EXPECT_EQ(t.copied.any(), 0) << "traced copy: " << t.copied.report();
  EXPECT_EQ(t.restored.any(), 0) << "traced keyframe: " << t.restored.report();
  std::printf("traced copy: %s\ntraced keyframe: %s\n", t.copied.report().c_str(),
              t.restored.report().c_str());
}

}  // namespace
}  // namespace tv
