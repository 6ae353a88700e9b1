#pragma once
// A level shaped like bump.lua's platformer demo, as it was when a traced re-run of a real
// game's recording first disagreed with the game: a player that walks, jumps and slides on
// blocks, guardians it slides on, grenades and debris that bounce off blocks, and many puffs of
// smoke around the player that its filter ignores — in 64 px cells, so a player's move meets
// a hundred candidates or more, most of them ignored.
//
//   +----------------------------------------------------------------+
//   |   ░░ ░  ░░░                                      ▒▒           |
//   |  ░ ░░ ░P░ ░    ####   .  .                ▒▒    ▒▒  G        |
//   | ░░░ ░ ░██░ ░░        .   ########          ▒▒    ▒▒ GG        |
//   |################################################################|
//   P player, ░ puffs, # blocks, G guardian, . debris, ▒ walls
//
// Every call goes through `Calls`, so a test can make each one twice (two worlds in step) and
// compare what came back.

#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "tv/sim/rng.hpp"
#include "tv/world.hpp"

namespace tv::test {

enum class Kind : std::uint8_t { none, block, guardian, player, grenade, debris, puff };

// What a level asks of a world: the test decides how each move is made (traced or not, which
// entry point) and what it compares.
struct Calls {
  std::function<ItemId(const Rect&)> add;
  std::function<void(ItemId)> remove;
  std::function<void(ItemId, const Rect&)> update;
  // A move of `id` to `goal` with this filter; returns where it ended and its collisions.
  std::function<MoveResult(ItemId, Vec2, Filter)> move;
};

class SmokyLevel {
 public:
  static constexpr double kCell = 64.0;
  static constexpr double kDt = 1.0 / 60.0;
  static constexpr double kGravity = 1000.0;

  explicit SmokyLevel(std::uint64_t seed) : rng_(seed) {}

  // The filters of the demo: the player slides on blocks and guardians and ignores the rest;
  // grenades and debris bounce off blocks (and grenades off guardians).
  [[nodiscard]] ResponseId answer(ItemId item, ItemId other) const {
    const Kind a = kindOf(item), b = kindOf(other);
    switch (a) {
      case Kind::player:
        return b == Kind::block || b == Kind::guardian ? response::slide : response::ignore;
      case Kind::grenade:
        return b == Kind::block || b == Kind::guardian ? response::bounce : response::ignore;
      case Kind::debris:
        return b == Kind::block ? response::bounce : response::ignore;
      default:
        return response::ignore;
    }
  }
  [[nodiscard]] Kind kindOf(ItemId id) const {
    return id.index < kinds_.size() ? kinds_[id.index] : Kind::none;
  }

  void build(Calls& c) {
    // The floor, in blocks of 32 px, a few of them a pixel higher (as a hand-made map has).
    for (int i = 0; i < 60; ++i) {
      const double lift = (i % 11 == 3) ? 1.0 : 0.0;
      add(c, {i * 32.0, kFloor - lift, 32.0, 32.0 + lift}, Kind::block);
    }
    // Walls at both ends and platforms at several heights, of many sizes.
    add(c, {-32.0, kFloor - 640.0, 32.0, 640.0}, Kind::block);
    add(c, {60 * 32.0, kFloor - 640.0, 32.0, 640.0}, Kind::block);
    for (int i = 0; i < 14; ++i) {
      const double w = 32.0 * static_cast<double>(1 + rng_.below(6));
      const double x = std::floor(rng_.uniform(0.0, 1800.0));
      const double y = kFloor - 96.0 - 64.0 * static_cast<double>(rng_.below(6));
      add(c, {x, y, w, 16.0 + 16.0 * static_cast<double>(rng_.below(2))}, Kind::block);
    }
    for (int i = 0; i < 3; ++i) {
      guardians_.push_back(
          add(c, {300.0 + 500.0 * i, kFloor - 110.0, 42.0, 110.0}, Kind::guardian));
    }
    player_ = add(c, {779.0, kFloor - 64.0, 32.0, 64.0}, Kind::player);
    playerRect_ = {779.0, kFloor - 64.0, 32.0, 64.0};
  }

  // One frame of the game, as the demo's update makes it.
  void frame(Calls& c) {
    ++frame_;
    const auto answering = [this](ItemId a, ItemId b) { return answer(a, b); };
    const Filter filter(answering);  // refers to `answering`, which must outlive it
    movePlayer(c, filter);
    spawnPuffs(c);
    updatePuffs(c);
    moveProjectiles(c, filter);
    if (frame_ % 45 == 0) throwGrenade(c);
  }

  [[nodiscard]] ItemId player() const { return player_; }
  [[nodiscard]] std::size_t puffs() const { return puffs_.size(); }
  [[nodiscard]] std::size_t bodies() const { return bodies_.size(); }

 private:
  static constexpr double kFloor = 1781.0;

  struct Puff {
    ItemId id;
    Rect rect;
    Vec2 v;
    double life;
  };
  struct Body {
    ItemId id;
    Rect rect;
    Vec2 v;
    double life;
  };

  ItemId add(Calls& c, const Rect& r, Kind k) {
    const ItemId id = c.add(r);
    if (kinds_.size() <= id.index) kinds_.resize(id.index + 1, Kind::none);
    kinds_[id.index] = k;
    return id;
  }
  void remove(Calls& c, ItemId id) {
    c.remove(id);
    kinds_[id.index] = Kind::none;
  }

  void movePlayer(Calls& c, const Filter& filter) {
    // Walks one way then the other, jumps now and then, uses the jetpack while it is up.
    const int phase = (frame_ / 150) % 4;
    const double walk = phase == 0 ? 180.0 : phase == 2 ? -180.0 : (phase == 1 ? 40.0 : -60.0);
    playerV_.x = walk;
    if (onGround_ && frame_ % 70 == 0) playerV_.y = -520.0;
    jetpack_ = !onGround_ && frame_ % 140 < 40;
    if (jetpack_) playerV_.y -= 1500.0 * kDt;
    playerV_.y += kGravity * kDt;
    const Vec2 goal{playerRect_.x + playerV_.x * kDt, playerRect_.y + playerV_.y * kDt};
    const MoveResult r = c.move(player_, goal, filter);
    onGround_ = false;
    for (const Collision& col : r.collisions) {
      if (col.normal.y < 0) onGround_ = true;
      if (col.normal.y != 0) playerV_.y = 0.0;
      if (col.normal.x != 0) playerV_.x = 0.0;
    }
    playerRect_ = playerRect_.at(r.position);
  }

  void spawnPuffs(Calls& c) {
    // Smoke under the feet while walking on the ground, a plume while the jetpack is on.
    const int n = jetpack_ ? 4 : (onGround_ && playerV_.x != 0.0 ? 2 : 1);
    for (int i = 0; i < n && puffs_.size() < 140; ++i) {
      const double s = rng_.uniform(2.0, 8.0);
      const Rect r{playerRect_.x + rng_.uniform(-12.0, 40.0),
                   playerRect_.bottom() - rng_.uniform(0.0, 40.0), s, s};
      puffs_.push_back({add(c, r, Kind::puff), r,
                        {rng_.uniform(-30.0, 30.0), rng_.uniform(-70.0, -10.0)},
                        rng_.uniform(0.8, 2.5)});
    }
  }

  void updatePuffs(Calls& c) {
    // Puffs rise, drift and grow (world:update with a new size), then go.
    for (std::size_t i = 0; i < puffs_.size();) {
      Puff& p = puffs_[i];
      p.life -= kDt;
      if (p.life <= 0.0) {
        remove(c, p.id);
        puffs_[i] = puffs_.back();
        puffs_.pop_back();
        continue;
      }
      const double grow = 6.0 * kDt;
      p.rect = {p.rect.x + p.v.x * kDt - grow / 2, p.rect.y + p.v.y * kDt - grow / 2,
                p.rect.w + grow, p.rect.h + grow};
      c.update(p.id, p.rect);
      ++i;
    }
  }

  void throwGrenade(Calls& c) {
    const ItemId g = guardians_[rng_.below(guardians_.size())];
    (void)g;
    const Rect r{playerRect_.x + rng_.uniform(-200.0, 200.0), kFloor - 300.0, 11.0, 11.0};
    bodies_.push_back({add(c, r, Kind::grenade), r,
                       {rng_.uniform(-200.0, 200.0), rng_.uniform(-300.0, 0.0)}, 3.0});
  }

  void moveProjectiles(Calls& c, const Filter& filter) {
    for (std::size_t i = 0; i < bodies_.size();) {
      bodies_[i].life -= kDt;
      if (bodies_[i].life <= 0.0) {
        const Body b = bodies_[i];  // debris is added to bodies_ below
        // A grenade bursts into debris where it is.
        if (kindOf(b.id) == Kind::grenade) {
          for (int k = 0; k < 8 && bodies_.size() < 120; ++k) {
            const double s = rng_.uniform(3.0, 9.0);
            const Rect r{b.rect.x + rng_.uniform(-4.0, 4.0), b.rect.y - rng_.uniform(0.0, 6.0), s,
                         s};
            bodies_.push_back({add(c, r, Kind::debris), r,
                               {rng_.uniform(-250.0, 250.0), rng_.uniform(-400.0, -50.0)},
                               rng_.uniform(1.0, 3.0)});
          }
        }
        remove(c, bodies_[i].id);
        bodies_[i] = bodies_.back();
        bodies_.pop_back();
        continue;
      }
      Body& m = bodies_[i];
      m.v.y += kGravity * kDt;
      const MoveResult r = c.move(m.id, {m.rect.x + m.v.x * kDt, m.rect.y + m.v.y * kDt}, filter);
      for (const Collision& col : r.collisions) {
        if (col.normal.x != 0) m.v.x = -m.v.x * 0.5;
        if (col.normal.y != 0) m.v.y = -m.v.y * 0.5;
      }
      m.rect = m.rect.at(r.position);
      ++i;
    }
  }

  sim::Rng rng_;
  std::vector<Kind> kinds_;
  std::vector<ItemId> guardians_;
  std::vector<Puff> puffs_;
  std::vector<Body> bodies_;
  ItemId player_;
  Rect playerRect_;
  Vec2 playerV_;
  bool onGround_ = false;
  bool jetpack_ = false;
  int frame_ = 0;
};

}  // namespace tv::test
