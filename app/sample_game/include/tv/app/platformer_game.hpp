#pragma once
// The sample platformer's game logic (tv-example-platformer), shared with the tests that record
// it, validate it and re-run it under other movers, and with the benchmark. See
// app/examples/platformer.cpp.

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "tv/mover.hpp"
#include "tv/record/recorder.hpp"
#include "tv/timestep.hpp"
#include "tv/world.hpp"

namespace tv::example {

constexpr double kTile = 16.0;
constexpr double kGravity = 900.0;       // px/s²
constexpr double kRun = 120.0;           // px/s
constexpr double kJump = -330.0;         // px/s
constexpr double kBulletSpeed = 1920.0;  // px/s: 32 px a tick, far more than wall + bullet
constexpr int kColumns = 40;
constexpr int kFloorRow = 12;
constexpr double kWallX = 30 * kTile + 7;  // a 2 px wall standing on the floor

struct Bullet {
  tv::ItemId item;
  double vx = 0;
  double fromX = 0;  // where it was fired: past the wall's far side means it went through
};

class Game {
 public:
  explicit Game(bool naive) : naive_(naive), world_(kTile), mover_(tv::parseMover("continuous")) {}

  tv::World& world() { return world_; }

  void build(tv::Recorder* rec) {
    for (int x = 0; x < kColumns; ++x) addTile(rec, x, kFloorRow);
    for (int x = 10; x < 16; ++x)
      addTile(rec, x, kFloorRow - 4);  // a ledge to jump on and fall off
    addTile(rec, -1, kFloorRow - 1);
    addTile(rec, kColumns, kFloorRow - 1);
    wall_ = world_.add({kWallX, (kFloorRow - 6) * kTile, 2, 6 * kTile});
    if (rec) rec->label(wall_, "wall", "wall");
    player_ = world_.add({2 * kTile, (kFloorRow - 1) * kTile - 14, 10, 14});
    if (rec) rec->label(player_, "player", "player");
  }

  // One physics tick of the script: run, jump now and then, turn at the ends, shoot.
  void tick(std::uint64_t tick, double dt, tv::Recorder* rec) {
    if (tick % 70 == 20 && onGround_) vy_ = kJump;
    const tv::Rect p = world_.rect(player_);
    if (p.x > (kColumns - 3) * kTile) facing_ = -1;
    if (p.x < 2 * kTile) facing_ = 1;
    vy_ += kGravity * dt;
    movePlayer({p.x + facing_ * kRun * dt, p.y + vy_ * dt});
    if (tick % 15 == 0) shoot(rec);
    moveBullets(dt);
  }

  [[nodiscard]] int fired() const { return fired_; }
  [[nodiscard]] int stopped() const { return stopped_; }
  [[nodiscard]] int through() const { return through_; }

  std::uint64_t ticks = 0;

 private:
  void addTile(tv::Recorder* rec, int x, int y) {
    const tv::ItemId t = world_.add({x * kTile, y * kTile, kTile, kTile});
    if (rec) rec->label(t, "tile " + std::to_string(x) + "," + std::to_string(y), "tile");
  }

  bool isBullet(tv::ItemId id) const {
    for (const Bullet& b : bullets_) {
      if (b.item == id) return true;
    }
    return false;
  }

  void movePlayer(tv::Vec2 goal) {
    onGround_ = false;
    if (!naive_) {
      const auto filter = [this](tv::ItemId, tv::ItemId other) {
        return isBullet(other) ? tv::response::ignore : tv::response::slide;
      };
      for (const tv::Collision& c : mover_.move(world_, player_, goal, filter).collisions)
        land(c.normal);
      return;
    }
    world_.update(player_, goal);
    pushOut(player_, true);
  }

  void land(tv::Vec2 normal) {
    if (normal.y < 0) onGround_ = true;
    if (normal.y != 0) vy_ = 0;
  }

  // The naive resolution: out of every overlapping solid along its shallowest axis.
  bool pushOut(tv::ItemId id, bool player) {
    bool hit = false;
    tv::Rect r = world_.rect(id);
    for (const tv::ItemId o : world_.queryRect(r, id)) {
      if (o == player_ || isBullet(o)) continue;
      const tv::Rect s = world_.rect(o);
      const double left = r.right() - s.x, right = s.right() - r.x;
      const double up = r.bottom() - s.y, down = s.bottom() - r.y;
      const double dx = left < right ? -left : right, dy = up < down ? -up : down;
      if (std::fabs(dx) < std::fabs(dy)) {
        r.x += dx;
      } else {
        r.y += dy;
        if (player) land({0, dy < 0 ? -1.0 : 1.0});
      }
      hit = true;
    }
    if (hit) world_.update(id, r);
    return hit;
  }

  void shoot(tv::Recorder* rec) {
    const tv::Rect p = world_.rect(player_);
    Bullet b;
    b.vx = p.x < kWallX ? kBulletSpeed : -kBulletSpeed;
    b.fromX = p.x;
    b.item = world_.add({p.x + 3, p.y + 4, 4, 4});
    if (rec) rec->label(b.item, "bullet " + std::to_string(fired_), "bullet");
    ++fired_;
    bullets_.push_back(b);
  }

  void moveBullets(double dt) {
    for (std::size_t i = 0; i < bullets_.size();) {
      Bullet& b = bullets_[i];
      const tv::Rect r = world_.rect(b.item);
      const tv::Vec2 goal{r.x + b.vx * dt, r.y};
      bool hit = false;
      if (!naive_) {
        const auto filter = [this](tv::ItemId, tv::ItemId other) {
          return other == player_ || isBullet(other) ? tv::response::ignore : tv::response::touch;
        };
        hit = !mover_.move(world_, b.item, goal, filter).collisions.empty();
      } else {
        world_.update(b.item, goal);
        hit = pushOut(b.item, false);
      }
      const tv::Rect now = world_.rect(b.item);
      const bool gone = now.x < -kTile || now.x > (kColumns + 1) * kTile;
      if (hit || gone) {
        const bool fromLeft = b.fromX < kWallX;
        const bool past = fromLeft ? now.x >= kWallX + 2 : now.right() <= kWallX;
        if (past) {
          ++through_;
        } else {
          ++stopped_;
        }
        world_.remove(b.item);
        bullets_.erase(bullets_.begin() + static_cast<std::ptrdiff_t>(i));
        continue;
      }
      ++i;
    }
  }

  bool naive_;
  tv::World world_;
  tv::Mover mover_;
  tv::ItemId player_, wall_;
  double vy_ = 0;
  double facing_ = 1;
  bool onGround_ = false;
  std::vector<Bullet> bullets_;
  int fired_ = 0, stopped_ = 0, through_ = 0;
};

struct Played {
  std::uint64_t ticks = 0;
  int fired = 0, stopped = 0, through = 0;
};

// Plays `frames` rendered frames (a hitch every 7th); records into `rec` when given.
inline Played play(std::uint64_t frames, bool naive, tv::Recorder* rec) {
  Game game(naive);
  tv::FixedStep step(1.0 / 60.0);
  if (rec) {
    game.world().attach(*rec);
    rec->attach(step);
  }
  game.build(rec);
  for (std::uint64_t frame = 0; frame < frames; ++frame) {
    const double frameTime = frame % 7 == 3 ? 1.0 / 30.0 : 1.0 / 60.0;  // a hitch now and then
    const int ticks = step.advance(frameTime);
    for (int t = 0; t < ticks; ++t) game.tick(game.ticks++, step.step(), rec);
  }
  if (rec) rec->close();
  return {game.ticks, game.fired(), game.stopped(), game.through()};
}

}  // namespace tv::example
