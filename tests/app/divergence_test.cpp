// The debugger can't contradict itself about a replay that differs from its recording (a bug,
// or a hand-edited file): the picture drawn from such a replay is labelled as not what the game
// got — in the world view's corner and in the inspector, with the same words the status bar
// and the timeline use (tests/viewer/divergence_test.cpp drives the debugger) — and tv-render's
// picture of it carries the label too.
#include <gtest/gtest.h>

#include <bit>
#include <string>
#include <vector>

#include "app/drawn_text.hpp"
#include "imgui.h"
#include "record/recording_kit.hpp"
#include "tv/record/recorder.hpp"
#include "tv/record/replay.hpp"
#include "tv/ui/replay_source.hpp"
#include "tv/ui/still.hpp"

namespace tv::ui {
namespace {

// The player walks right towards a wall, one move per frame, 32 frames, a keyframe every 16.
// With `edit`, frame 6's goal is pushed 30 px further on disk (its chunk's checksum fixed up,
// as a careless tool would): the file opens, but the replayed move stops at the wall where the
// recorded one went on — and frame 7's move (to an absolute goal) brings the player back.
//
//   player ->             |wall|
//   [##]  . . . .  (6') ->|    |      6': the edited goal, into the wall
//   ========================== floor
std::vector<std::uint8_t> walk(bool edit) {
  World world(16);
  world.add({0, 32, 160, 16});  // floor
  world.add({40, 0, 4, 32});    // wall
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
  return file;
}

std::string oneLine(std::string s) {
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

TEST(Divergence, TheHandEditedFileDivergesAtTheEditedMoveUntracedAndTraced) {
  Replay untraced = Replay::fromBytes(walk(true));
  const auto d = untraced.validate();
  ASSERT_TRUE(d);
  EXPECT_EQ(d->frame, 6u);
  EXPECT_EQ(d->call, 0u);
  EXPECT_EQ(d->got, "(32, 16)");  // against the wall
  Replay traced = Replay::fromBytes(walk(true));
  EXPECT_TRUE(traced.validate({}, Replay::Tracing::on));
  // The control: the file as the game wrote it replays bit for bit.
  EXPECT_FALSE(Replay::fromBytes(walk(false)).validate({}, Replay::Tracing::on));
}

TEST(Divergence, APictureAtTheDivergingMoveIsLabelledNotWhatTheGameGot) {
  ReplaySource s(Replay::fromBytes(walk(true)), "edited.tvrec");
  s.goTo(6);
  ASSERT_TRUE(s.pictureDivergence());
  EXPECT_EQ(s.pictureDivergence()->frame, 6u);
  const std::string label = s.pictureLabel();
  EXPECT_EQ(label.rfind("NOT WHAT THE GAME GOT: the replay differs from the recording at frame 6 "
                        "call 0, move player: position recorded (",
                        0),
            0u)
      << label;
  EXPECT_NE(label.find("replayed (32, 16)"), std::string::npos) << label;
  // notes() is what the world view's corner shows.
  const std::vector<std::string> notes = s.notes();
  EXPECT_NE(std::find(notes.begin(), notes.end(), label), notes.end());
}

TEST(Divergence, APictureReplayedThroughAnEarlierDivergenceSaysSoWhereTheFrameAloneWouldNot) {
  // Frame 15, seeked to directly: its world comes from the keyframe at 0 through the edited
  // move at frame 6, which lies before the 8 frames of history re-traced for the picture.
  ReplaySource s(Replay::fromBytes(walk(true)), "edited.tvrec");
  s.goTo(15);
  EXPECT_FALSE(s.divergence()) << "frame 15's own calls match: the frame alone says nothing";
  ASSERT_TRUE(s.pictureDivergence()) << "but the replay under the picture diverged at frame 6";
  EXPECT_EQ(s.pictureDivergence()->frame, 6u);
  EXPECT_EQ(s.pictureLabel().rfind("MAY NOT BE WHAT THE GAME GOT: the replay differed from the "
                                   "recording earlier, at frame 6 call 0, move player",
                                   0),
            0u)
      << s.pictureLabel();
  // Played on frame by frame from the divergence, the label stays while the world came
  // through it.
  ReplaySource played(Replay::fromBytes(walk(true)), "edited.tvrec");
  for (std::uint64_t f = 6; f <= 15; ++f) played.goTo(f);
  EXPECT_TRUE(played.pictureDivergence());
}

TEST(Divergence, APictureRebuiltFromALaterKeyframeIsNotLabelled) {
  // Frame 28: its history (20..28) starts after the keyframe at 16, whose world is the one the
  // game recorded — the edited move is not under this picture.
  ReplaySource s(Replay::fromBytes(walk(true)), "edited.tvrec");
  s.goTo(28);
  EXPECT_FALSE(s.pictureDivergence());
  EXPECT_EQ(s.pictureLabel(), "");
}

TEST(Divergence, TheFileAsTheGameWroteItIsNeverLabelled) {  // the control
  ReplaySource s(Replay::fromBytes(walk(false)), "game.tvrec");
  for (const std::uint64_t f : {6u, 7u, 15u, 28u}) {
    s.goTo(f);
    EXPECT_FALSE(s.pictureDivergence()) << "frame " << f;
    EXPECT_EQ(s.pictureLabel(), "") << "frame " << f;
  }
}

// tv-render's picture: the still it draws (the same composition as the debugger's screenshot),
// read back from ImGui's draw lists.
class StillText : public ::testing::Test {
 protected:
  void SetUp() override {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = {1280, 720};
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  }
  void TearDown() override { ImGui::DestroyContext(); }

  // The text of the world view's corner (HUD) in tv-render's picture of `file`.
  static std::string hudOf(const std::vector<std::uint8_t>& file, const std::string& name,
                           std::uint64_t frame, bool firstFailure) {
    const std::string path = ::testing::TempDir() + name;
    tvtest::writeFile(path, file);
    PictureOptions o;
    o.firstFailure = firstFailure;
    RecordingFlags r;
    r.path = path;
    r.frame = frame;
    r.item = "player";
    Still still(o, r);
    still.beginImage();
    std::string text;
    for (int i = 0; i < o.frames; ++i) {
      ImGui::NewFrame();
      still.drawFrame(ImGui::GetIO().DisplaySize);
      ImGui::Render();
    }
    return oneLine(tvtest::drawnText("HUD"));
  }
};

TEST_F(StillText, TvRendersPictureOfTheDivergingFrameCarriesTheLabel) {
  const std::string hud = hudOf(walk(true), "tv_edited.tvrec", 6, false);
  EXPECT_NE(hud.find("NOT WHAT THE GAME GOT: the replay differs from the recording at frame 6 "
                     "call 0, move player: position recorded"),
            std::string::npos)
      << hud;
  // --first-failure goes there by itself: the divergence is the run's first failure.
  const std::string first = hudOf(walk(true), "tv_edited_first.tvrec", 0, true);
  EXPECT_NE(first.find("NOT WHAT THE GAME GOT"), std::string::npos) << first;
}

TEST_F(StillText, TvRendersPictureOfTheFileAsWrittenHasNoLabel) {  // the control
  const std::string hud = hudOf(walk(false), "tv_written.tvrec", 6, false);
  EXPECT_NE(hud.find("frame 6"), std::string::npos) << hud;  // the corner was read
  EXPECT_EQ(hud.find("WHAT THE GAME GOT"), std::string::npos) << hud;
}

}  // namespace
}  // namespace tv::ui
