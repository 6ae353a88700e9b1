// The debugger can't contradict itself: a recording whose replay differs from it (here a
// hand-edited file) is said to diverge by the status bar, the timeline and the inspector in the
// same words, the picture is labelled as not what the game got, and nothing says "valid".
// (tests/app/divergence_test.cpp: the source's label, and tv-render's picture.)

#include <algorithm>
#include <bit>
#include <string>

#include "driver.hpp"
#include "record/recording_kit.hpp"
#include "tv/record/replay.hpp"

namespace tv::viewer {
namespace {

// The player walks right towards a wall, a move per frame, 32 frames (keyframes at 0 and 16);
// with `edit`, frame 6's goal is pushed 30 px on, into the wall, on disk.
//
//   player ->             |wall|
//   [##]  . . . .  (6') ->|    |
//   ========================== floor
std::string walk(bool edit) {
  World world(16);
  world.add({0, 32, 160, 16});
  world.add({40, 0, 4, 32});
  RecorderOptions o;
  o.keyframeEvery = 16;
  Recorder rec(o);
  world.attach(rec);
  const ItemId player = world.add({0, 16, 8, 16});
  rec.label(player, "player", "player");
  for (int f = 0; f < 32; ++f) {
    rec.frame();
    world.move(player, world.rect(player).position() + Vec2{0.5 + 0.01234567 * f, 0.0});
  }
  world.detach();
  std::vector<std::uint8_t> file = rec.bytes();
  if (edit) {
    const std::vector<CallInfo> calls = Replay::fromBytes(file).calls(6);
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(calls.at(0).goal.x);
    EXPECT_TRUE(tvtest::replaceDouble(file, calls[0].offset, bits, calls[0].goal.x + 30.0));
  }
  const std::string path = ::testing::TempDir() + (edit ? "tv_viewer_edited.tvrec" : "tv_viewer_written.tvrec");
  tvtest::writeFile(path, file);
  return path;
}

std::string oneLine(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '\n' || c == ' ') {
      if (!out.empty() && out.back() != ' ') out += ' ';
    } else {
      out += c;
    }
  }
  return out;
}

bool saysValid(const std::vector<std::string>& status) {
  return std::any_of(status.begin(), status.end(),
                     [](const std::string& s) { return s.rfind("valid", 0) == 0; });
}

using DebuggerDivergence = DebuggerDriver;

TEST_F(DebuggerDivergence, StatusBarTimelineInspectorAndPictureSayTheSameThingAtTheDivergingMove) {
  open({walk(true), "--frame", "6", "--item", "player"});
  frames(2);
  const auto d = dbg().divergence();
  ASSERT_TRUE(d);
  EXPECT_EQ(d->frame, 6u);  // where the timeline's mark stands
  EXPECT_EQ(d->call, 0u);
  const std::string words = "frame 6 call 0, move player: position recorded (";
  const std::vector<std::string> status = dbg().status();
  ASSERT_FALSE(status.empty());
  EXPECT_EQ(status.front().rfind("DIVERGED at " + words, 0), 0u) << status.front();
  EXPECT_NE(status.front().find("replayed (32, 16)"), std::string::npos) << status.front();
  EXPECT_FALSE(saysValid(status));
  // What is drawn: the timeline's status row, the inspector, the picture's corner.
  const std::string timeline = oneLine(drawnText("Timeline"));
  EXPECT_NE(timeline.find("DIVERGED at " + words), std::string::npos) << timeline;
  EXPECT_EQ(timeline.find("valid"), std::string::npos) << timeline;
  const std::string label = "NOT WHAT THE GAME GOT: the replay differs from the recording at " + words;
  const std::string details = oneLine(drawnText("Details"));
  EXPECT_NE(details.find(label), std::string::npos) << details;
  const std::string hud = oneLine(drawnText("HUD"));
  EXPECT_NE(hud.find(label), std::string::npos) << hud;
}

TEST_F(DebuggerDivergence, ElsewhereTheStatusBarStillSaysItAndGoGoesThere) {
  open({walk(true), "--frame", "28"});
  frames(2);
  // The picture at 28 is rebuilt from the keyframe at 16: not labelled; the file diverges all
  // the same, and the status bar says where.
  EXPECT_EQ(oneLine(drawnText("HUD")).find("WHAT THE GAME GOT"), std::string::npos);
  const std::vector<std::string> status = dbg().status();
  ASSERT_FALSE(status.empty());
  EXPECT_EQ(status.front().rfind("DIVERGED at frame 6 call 0, move player", 0), 0u) << status.front();
  EXPECT_FALSE(saysValid(status));
  dbg().goToDivergence();
  frames(2);
  EXPECT_EQ(dbg().currentTick(), 6u);
  ASSERT_TRUE(dbg().session().primary().call());
  EXPECT_EQ(*dbg().session().primary().call(), 0u);
  EXPECT_NE(oneLine(drawnText("HUD")).find("NOT WHAT THE GAME GOT"), std::string::npos);
}

TEST_F(DebuggerDivergence, TheFileAsTheGameWroteItIsValidAndNothingSaysOtherwise) {  // the control
  open({walk(false), "--frame", "6", "--item", "player"});
  frames(2);
  EXPECT_FALSE(dbg().divergence());
  const std::vector<std::string> status = dbg().status();
  EXPECT_TRUE(std::find(status.begin(), status.end(), "valid: the replay matches the recording") !=
              status.end());
  const std::string all = drawnText();
  EXPECT_EQ(all.find("DIVERGED"), std::string::npos);
  EXPECT_EQ(all.find("WHAT THE GAME GOT"), std::string::npos);
}

}  // namespace
}  // namespace tv::viewer
