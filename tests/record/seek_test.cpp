// Specification of seeking: the world at frame k of a long recording, reached from the nearest
// keyframe, equals the game's world at frame k and the world replayed from the start (state
// hashes).

#include <gtest/gtest.h>

#include <vector>

#include "tv/mover.hpp"
#include "tv/record/recorder.hpp"
#include "tv/record/replay.hpp"
#include "tv/world.hpp"

namespace {

struct Long {
  std::vector<std::uint8_t> file;
  std::vector<std::uint64_t> hashAtEndOf;  // the game's world hash at the end of each frame
};

// 10^5 frames: four bodies bouncing in a box, moved by World::move and a Mover, and one added
// and removed now and then so keyframes carry free slots.
const Long& longRecording() {
  static const Long l = [] {
    Long out;
    tv::World w(16);
    w.add({0, 0, 320, 8});
    w.add({0, 232, 320, 8});
    w.add({0, 0, 8, 240});
    w.add({312, 0, 8, 240});
    tv::Recorder rec(tv::RecorderOptions{64});
    w.attach(rec);
    std::vector<tv::ItemId> b;
    std::vector<tv::Vec2> v;
    for (int i = 0; i < 4; ++i) {
      b.push_back(w.add({20.0 + 60 * i, 30.0 + 40 * i, 6, 6}));
      v.push_back({3.25 + i * 0.5, 2.125 - i * 0.75});
    }
    tv::Mover mover(tv::parseMover("adaptive"));
    tv::ItemId spark;
    for (int f = 0; f < 100000; ++f) {
      for (std::size_t i = 0; i < b.size(); ++i) {
        const tv::Vec2 goal = w.rect(b[i]).position() + v[i];
        const tv::MoveResult r = i % 2 ? mover.move(w, b[i], goal) : w.move(b[i], goal);
        for (const tv::Collision& c : r.collisions) {
          if (c.normal.x != 0) v[i].x = -v[i].x;
          if (c.normal.y != 0) v[i].y = -v[i].y;
        }
      }
      if (f % 50 == 10) spark = w.add({100, 100, 2, 2});
      if (f % 50 == 30) w.remove(spark);
      out.hashAtEndOf.push_back(w.stateHash());
      rec.frame();
    }
    w.detach();
    out.file = rec.bytes();
    return out;
  }();
  return l;
}

TEST(Seek, FrameKFromTheNearestKeyframeEqualsTheGameAndAReplayFromTheStart) {
  const Long& l = longRecording();
  tv::Replay seeker = tv::Replay::fromBytes(l.file);
  ASSERT_EQ(seeker.frames(), 100001u);
  const std::uint64_t ks[] = {0, 1, 63, 64, 65, 4097, 77777, 99999, 12345, 3};  // backwards too
  for (const std::uint64_t k : ks) {
    seeker.seek(k);
    EXPECT_EQ(seeker.frame(), k);
    EXPECT_EQ(seeker.world().stateHash(), l.hashAtEndOf[k]) << "frame " << k;
  }
  // From the start, call by call: the same hashes on the way.
  tv::Replay stepper = tv::Replay::fromBytes(l.file);
  std::uint64_t checked = 0;
  while (!stepper.atEnd()) {
    ASSERT_FALSE(stepper.step());
    if (stepper.call() == stepper.callCount(stepper.frame()) && stepper.frame() % 997 == 0) {
      ASSERT_EQ(stepper.world().stateHash(), l.hashAtEndOf[stepper.frame()]);
      ++checked;
    }
  }
  EXPECT_GT(checked, 90u);
}

TEST(Seek, ToACallWithinAFrame) {
  const Long& l = longRecording();
  tv::Replay r = tv::Replay::fromBytes(l.file);
  r.seek(500, 2);
  EXPECT_EQ(r.frame(), 500u);
  EXPECT_EQ(r.call(), 2u);
  r.seek(500, 0);
  r.seek(499);
  EXPECT_EQ(r.world().stateHash(), l.hashAtEndOf[499]);
  EXPECT_THROW(r.seek(100001), tv::Error);
}

}  // namespace
