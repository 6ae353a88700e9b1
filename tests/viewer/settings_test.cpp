// What the debugger remembers between runs (settings.hpp), as a person who only opens
// recordings meets it: Help is seen once, and a recording's session leaves the scene
// settings as the last scene left them.
#include <filesystem>

#include "driver.hpp"
#include "settings.hpp"

namespace tv::viewer {
namespace {

class SavedSettings : public DebuggerDriver {
 protected:
  void SetUp() override {
    DebuggerDriver::SetUp();
    path_ = ::testing::TempDir() + "tv_settings_" + std::to_string(::getpid()) + ".txt";
    std::filesystem::remove(path_);
  }
  void TearDown() override {
    std::filesystem::remove(path_);
    DebuggerDriver::TearDown();
  }
  // A start as tv-debugger's main makes it: the settings file read if there is one, Help opened
  // when there is none; then Ctrl+Q, which saves.
  struct Run {
    std::unique_ptr<Debugger> debugger;
    Settings settings;
  };
  Run start(const std::vector<std::string>& given) {
    std::vector<std::string> args = {"tv-debugger"};
    args.insert(args.end(), given.begin(), given.end());
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    Run r;
    const bool loaded = r.settings.load(path_);
    r.debugger = std::make_unique<Debugger>(
        parseViewerOptions(static_cast<int>(argv.size()), argv.data()), loaded ? &r.settings : nullptr);
    if (!loaded) r.debugger->openHelp();
    return r;
  }
  void quit(Run& r) {
    r.debugger->store(r.settings);
    r.settings.setNumber("window.width", 1280);  // what main adds
    std::string error;
    ASSERT_TRUE(r.settings.save(path_, error)) << error;
  }
  std::string path_;
};

// `tv-debugger game.tvrec` on a fresh config, Ctrl+Q, again: Help opened every time (only the
// window size was saved, never that Help had been seen).
TEST_F(SavedSettings, HelpSeenWithARecordingIsNotShownAgain) {
  Run first = start({sampleRecording()});
  ASSERT_TRUE(first.debugger->helpOpen()) << "the first run opens Help";
  quit(first);
  Run second = start({sampleRecording()});
  EXPECT_FALSE(second.debugger->helpOpen()) << "Help was seen in the first run";
  Run scene = start({});
  EXPECT_FALSE(scene.debugger->helpOpen()) << "nor in a scene after it";
}

// What a recording's session saves does not reach the next scene start: the scene, its movers,
// follow and the overlays come back as the last scene left them. The control: the scene's own
// session does save them (the scene start below is not merely the default).
TEST_F(SavedSettings, ARecordingLeavesTheSceneSettingsAsTheSceneLeftThem) {
  Run scene = start({"--scene", "seam-walk", "--mover", "discrete"});
  scene.debugger->command(Command::follow);
  const bool followed = scene.debugger->following();
  quit(scene);
  Run recording = start({sampleRecording(), "--hide", "grid"});
  recording.debugger->command(Command::faster);  // the playback rate is a person's, kept
  quit(recording);
  Run again = start({});
  EXPECT_EQ(again.settings.get("scene"), "seam-walk");
  ASSERT_EQ(again.debugger->movers().size(), 1u);
  EXPECT_EQ(again.debugger->movers()[0].name(), "discrete");
  EXPECT_EQ(again.debugger->following(), followed);
  EXPECT_TRUE(again.debugger->panels()[0].overlays.grid) << "the recording's --hide stays there";
  EXPECT_TRUE(again.debugger->panels()[0].overlays.positions)
      << "a recording turns positions off for itself only";
  EXPECT_GT(again.settings.getNumber("speed", 1.0), 1.0);
}

}  // namespace
}  // namespace tv::viewer
