#pragma once
// A scripted game that makes every kind of recorded call (all responses, two user responses,
// a filter that ignores some pairs, removes and re-adds, a mid-game attach, every mover, a
// batch, queries and FixedStep frames), and helpers to read and tamper with recordings.

#include <zlib.h>

#include <bit>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tv/batch.hpp"
#include "tv/contact.hpp"
#include "tv/corner.hpp"
#include "tv/mover.hpp"
#include "tv/record/recorder.hpp"
#include "tv/timestep.hpp"
#include "tv/world.hpp"

namespace tvtest {

inline tv::Leg stickyResponse(const tv::Collision& c, tv::Vec2) {
  return {c.touch, c.touch, false};
}
inline tv::Leg springyResponse(const tv::Collision& c, tv::Vec2 goal) {
  return {c.touch, {goal.x, c.touch.y - 3.0}, false};
}

struct Script {
  tv::World world{16};
  tv::ItemId player, ghost, crate, spring;
  std::vector<tv::ItemId> bodies;
  std::vector<tv::Vec2> velocity;
  std::vector<tv::Mover> movers;
  tv::ItemId bullet[2];
  tv::ItemId jumper;
  int nudges = 0;  // corner corrections made
  std::vector<tv::Vec2> movePositions;  // after every world.move and mover.move, in order
  std::vector<std::uint32_t> freeAtAttach;
  std::uint64_t frames = 0;
  int framesToPlay = 40;
  std::uint32_t keyframeEvery = 4;

  std::vector<std::uint8_t> record() {
    tv::Recorder rec(tv::RecorderOptions{keyframeEvery});
    run(rec);
    return rec.bytes();
  }
  void recordTo(const std::string& path) {
    tv::Recorder rec(path, tv::RecorderOptions{keyframeEvery});
    run(rec);
  }

  void run(tv::Recorder& rec) {
    using tv::Vec2;
    // Before recording: the level, a user response, and some churn (free slots, generations).
    for (int x = 0; x < 20; ++x) world.add({x * 16.0, 160, 16, 16});
    world.add({0, -16, 320, 16});
    world.add({-16, 0, 16, 160});
    world.add({320, 0, 16, 160});
    world.add({200, 96, 2, 64});  // a thin wall
    const tv::ResponseId sticky = world.addResponse("sticky", &stickyResponse);
    const tv::ItemId junk1 = world.add({50, 50, 4, 4});
    const tv::ItemId junk2 = world.add({60, 50, 4, 4});
    world.add({70, 50, 4, 4});
    world.remove(junk1);
    world.remove(junk2);
    freeAtAttach = world.state().freeSlots;

    world.attach(rec);
    tv::FixedStep step(1.0 / 60.0);
    rec.attach(step);
    for (int x = 0; x < 20; ++x)
      rec.label(tv::ItemId{static_cast<std::uint32_t>(x), 0}, "tile " + std::to_string(x) + ",10",
                "tile");
    player = world.add({20, 130, 10, 13.7});  // reuses a free slot
    rec.label(player, "player", "player");
    ghost = world.add({60, 130, 12, 12});
    rec.label(ghost, "ghost", "pickup");
    crate = world.add({150, 140, 20, 20});
    rec.label(crate, "crate", "crate");
    spring = world.add({260, 150, 16, 10});
    for (int k = 0; k < 6; ++k) {
      bodies.push_back(world.add({20.0 + 25 * k, 40, 8, 8}));
      velocity.push_back({(97.3 + 13 * k) / 60.0, (61.7 - 9 * k) / 60.0});
      rec.label(bodies.back(), "body " + std::to_string(k), "body");
    }
    const char* kinds[] = {"discrete",   "sweep", "substep-discrete",
                           "continuous", "pixel", "adaptive"};
    for (const char* k : kinds) movers.emplace_back(tv::parseMover(k));
    // Far off to the right: a ceiling and a body jumping into its left end (2 px under it) every
    // 20 frames, corner-corrected (tv::moveCornered: its moves and a cornerNudge call).
    world.add({1000, 0, 32, 8});
    world.add({980, 100, 60, 8});
    jumper = world.add({994, 88, 8, 12});
    rec.label(jumper, "jumper", "body");
    double jumpVy = 0;
    bullet[0] = world.add({30, 120, 4, 4});
    bullet[1] = world.add({290, 120, 4, 4});
    tv::Batch batch;
    tv::Contacts contacts;
    tv::ResponseId springy = tv::response::slide;
    Vec2 pv{1.7, 0};

    for (int f = 0; f < framesToPlay; ++f) {
      const int ticks = step.advance(1.0 / 60.0);
      for (int t = 0; t < ticks; ++t) {
        const auto filter = [&](tv::ItemId, tv::ItemId other) -> tv::ResponseId {
          if (other == ghost) return tv::response::ignore;
          if (other == crate) return sticky;
          if (other == spring) return springy;
          if (other == bullet[0] || other == bullet[1]) return tv::response::cross;
          return tv::response::slide;
        };
        // The player: gravity, walking, every response.
        pv.y += 0.4;
        const tv::Rect pr = world.rect(player);
        const Vec2 goal = pr.position() + pv;
        (void)world.check(player, goal, filter);
        tv::MoveOptions bounds;
        bounds.broad = tv::BroadPhase::bounds;
        bounds.maxResponses = 8;
        const tv::MoveResult r =
            world.move(player, goal, filter, f % 2 ? bounds : tv::MoveOptions{});
        movePositions.push_back(r.position);
        tv::ContactOptions co;
        co.filter = filter;
        (void)contacts.update(world, player, co, r.collisions);
        (void)contacts.update(world, crate);
        for (const tv::Collision& c : r.collisions) {
          if (c.normal.y != 0) pv.y = 0;
          if (c.normal.x != 0) pv.x = -pv.x;
        }
        if (world.rect(player).x > 280 || world.rect(player).x < 10) pv.x = -pv.x;
        (void)world.project({100, 20, 6, 6}, {100 + f * 0.5, 170}, filter);
        // The bodies, each by its own mover, bouncing.
        for (std::size_t k = 0; k < bodies.size(); ++k) {
          const tv::Rect br = world.rect(bodies[k]);
          const tv::MoveResult m = movers[k].move(world, bodies[k], br.position() + velocity[k],
                                                  k % 2 ? tv::Filter(filter) : tv::Filter{});
          movePositions.push_back(m.position);
          (void)contacts.update(world, bodies[k], {}, m.collisions);
          for (const tv::Collision& c : m.collisions) {
            if (c.normal.x != 0) velocity[k].x = -velocity[k].x;
            if (c.normal.y != 0) velocity[k].y = -velocity[k].y;
          }
          (void)world.anyOverlap(world.rect(bodies[k]), bodies[k], [&](tv::ItemId, tv::ItemId o) {
            return o == ghost ? tv::response::ignore : tv::response::touch;
          });
        }
        // The jumper: gravity, a jump every 20 frames, corner correction.
        if (f % 20 == 0 && t == 0) jumpVy = -30;
        jumpVy += 2.5;
        const tv::Rect jr = world.rect(jumper);
        const tv::CornerMove jm = tv::moveCornered(world, jumper, {jr.x, jr.y + jumpVy});
        nudges += jm.nudged ? 1 : 0;
        for (const tv::Collision& c : jm.collisions)
          if (c.normal.y != 0) jumpVy = 0;
        // Two bullets meeting: moving against moving.
        const tv::BatchMove moves[2] = {
            {bullet[0], world.rect(bullet[0]).position() + Vec2{9, 0}},
            {bullet[1], world.rect(bullet[1]).position() + Vec2{-9, 0}}};
        batch.step(world, moves, [&](tv::ItemId, tv::ItemId o) {
          return o == ghost ? tv::response::ignore : tv::response::touch;
        });
        // Queries.
        (void)world.queryRect(world.rect(player).at(world.rect(player).position() + Vec2{-8, -8}),
                              player);
        (void)world.queryRect({0, 0, 64, 64});
        (void)world.queryPoint({33.5, 165});
        (void)world.querySegment({5, 100}, {315, 150});
        (void)world.anyOverlap({0, 150, 40, 20});
      }
      // Churn: a removed and re-added crate, a teleported bullet, a response added mid-game.
      if (f % 10 == 5) {
        (void)contacts.forget(world, crate);
        world.remove(crate);
        crate = world.add({150.0 + f, 140, 20, 20});
        rec.label(crate, "crate", "crate");
        world.update(bullet[0], tv::Vec2{30, 120});
        world.update(bullet[1], tv::Rect{290, 118, 4, 6});
      }
      if (f == 20) springy = world.addResponse("springy", &springyResponse);
      if (f == 30) rec.frame();  // an explicit frame mark as well as FixedStep's
    }
    world.detach();
    frames = rec.frames();
  }
};

inline std::vector<std::uint8_t> readFile(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

inline void writeFile(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream f(path, std::ios::binary);
  f.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

inline std::uint32_t le32(const std::vector<std::uint8_t>& b, std::size_t at) {
  return std::uint32_t{b[at]} | std::uint32_t{b[at + 1]} << 8 | std::uint32_t{b[at + 2]} << 16 |
         std::uint32_t{b[at + 3]} << 24;
}
inline void put32(std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i)
    b[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (8 * i));
}

// Chunk starts (the 8-byte chunk headers) of a well-formed recording.
inline std::vector<std::size_t> chunks(const std::vector<std::uint8_t>& b) {
  std::vector<std::size_t> out;
  std::size_t pos = 32;
  while (pos + 8 <= b.size()) {
    const std::uint32_t len = le32(b, pos);
    if (len == 0 || len > b.size() - pos - 8) break;
    out.push_back(pos);
    pos += 8 + len;
  }
  return out;
}

// Recomputes the checksum of the chunk holding byte `at`, as a tool that edits files would.
inline void fixChecksum(std::vector<std::uint8_t>& b, std::size_t at) {
  for (const std::size_t c : chunks(b)) {
    const std::uint32_t len = le32(b, c);
    if (at >= c + 8 && at < c + 8 + len) {
      put32(b, c + 4, static_cast<std::uint32_t>(::crc32(0, b.data() + c + 8, len)));
      return;
    }
  }
}

// Replaces the first raw double with these bits at or after `from`, fixing the checksum.
inline bool replaceDouble(std::vector<std::uint8_t>& b, std::uint64_t from, std::uint64_t bits,
                          double value) {
  for (std::size_t at = static_cast<std::size_t>(from); at + 8 <= b.size(); ++at) {
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < 8; ++i) v |= std::uint64_t{b[at + i]} << (8 * i);
    if (v != bits) continue;
    const auto nb = std::bit_cast<std::uint64_t>(value);
    for (std::size_t i = 0; i < 8; ++i) b[at + i] = static_cast<std::uint8_t>(nb >> (8 * i));
    fixChecksum(b, at);
    return true;
  }
  return false;
}

}  // namespace tvtest
