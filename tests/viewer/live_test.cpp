// A game watched while it runs: a game streaming its recorder's chunks to a listening debugger
// (on a thread of its own, as a real game would be), the debugger driven frame by frame.
#include "driver.hpp"

#include <atomic>
#include <filesystem>
#include <thread>

#include "record/live_kit.hpp"
#include "tv/record/replay.hpp"
#include "tv/sim/simulation.hpp"
#include "tv/ui/live_source.hpp"

namespace tv::viewer {
namespace {

class LiveDriver : public DebuggerDriver {
 protected:
  // Listens on a free port; returns the address a game connects to.
  std::string listen(std::vector<std::string> more = {}) {
    std::vector<std::string> args = {"--listen", "127.0.0.1:0"};
    args.insert(args.end(), more.begin(), more.end());
    open(args);
    live_ = dynamic_cast<ui::LiveSource*>(&dbg().session().primary());
    return live_->receiver().address();
  }
  // Debugger frames until `ok` holds (10 s at most).
  bool until(const std::function<bool()>& ok) {
    return tvtest::eventually([&] {
      frame();
      return ok();
    });
  }
  ui::LiveSource& live() { return *live_; }

 private:
  ui::LiveSource* live_ = nullptr;
};

LiveOptions gameTo(const std::string& address, bool control) {
  LiveOptions o;
  o.address = address;
  o.control = control;
  o.retrySeconds = 0.05;
  o.onMessage = [](std::string_view) {};
  return o;
}

// Frames appear as they arrive and the view follows the newest one.
TEST_F(LiveDriver, FramesShowAsTheyArriveAndTheViewFollowsTheNewest) {
  const std::string address = listen();
  ASSERT_TRUE(dbg().live());
  frames(2);
  EXPECT_NE(drawnText("HUD").find("waiting for a game at " + address), std::string::npos)
      << drawnText("HUD");
  Recorder rec(gameTo(address, false));
  tvtest::ThreadedGame game(rec);
  ASSERT_TRUE(until([&] { return live().connected() && live().lastFrame() >= 20; }));
  ASSERT_TRUE(until([&] { return dbg().currentTick() >= 20; }));
  EXPECT_TRUE(dbg().followingLive());
  // The traced item is the busiest one, its moves drawn; the world holds the game's items.
  EXPECT_GT(dbg().session().primary().world().count(), 100u);
  // A person who scrubs back stops following; the frames keep coming.
  const std::uint64_t at = dbg().currentTick();
  dbg().command(Command::stepBack);
  EXPECT_FALSE(dbg().followingLive());
  const std::uint64_t held = dbg().currentTick();
  EXPECT_EQ(held, at - 1);
  ASSERT_TRUE(until([&] { return live().lastFrame() > at + 10; }));
  EXPECT_EQ(dbg().currentTick(), held);
  // Play follows the newest again.
  dbg().command(Command::pause);
  ASSERT_TRUE(until([&] { return dbg().currentTick() > at + 10; }));
  game.stop();
}

// A live game whose bodies read their contacts (the one-way-rise scene streaming, on a thread of
// its own): the debugger shows its contact events and grounds as it shows a recording's, and the
// legend lists their colours.
TEST_F(LiveDriver, AGamesContactEventsAndGroundAreShownLive) {
  const std::string address = listen();
  Recorder rec(gameTo(address, false));
  std::atomic<bool> stop{false};
  const sim::SceneDef& scene = sim::findScene("one-way-rise");
  sim::Simulation sim(scene, scene.defaults(), parseMover("continuous"));
  const ItemId rider = sim.bodies()[0].item, platform = sim.bodies()[1].item;
  sim.attach(rec);
  std::thread game([&] {
    for (int t = 0; t < 400 && !stop.load(); ++t) {
      sim.tick();
      rec.frame();
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  });
  ASSERT_TRUE(until([&] { return live().connected() && dbg().currentTick() >= 10; }));
  dbg().command(Command::pause);
  frames(2);
  ui::Source& src = dbg().session().primary();
  EXPECT_TRUE(src.hasContacts());
  bool riderEvent = false;
  for (const sim::ContactAt& e : src.contactEvents()) riderEvent |= e.event.item == rider;
  EXPECT_TRUE(riderEvent) << "frame " << dbg().currentTick();
  const auto g = src.ground(rider);
  ASSERT_TRUE(g.has_value());
  EXPECT_EQ(g->item, platform) << "the rider stands on its platform";
  stop.store(true);
  game.join();
  sim.detach();
}

// Pausing in the debugger pauses a game that allows it; Step lets one frame pass.
TEST_F(LiveDriver, PauseHoldsTheGameAndStepLetsOneFramePass) {
  const std::string address = listen();
  Recorder rec(gameTo(address, true));
  tvtest::ThreadedGame game(rec);
  ASSERT_TRUE(until([&] { return live().controllable() && live().lastFrame() >= 10; }));
  dbg().command(Command::pause);  // hold the game
  EXPECT_TRUE(dbg().paused());
  // Held at its next frame mark: wait until it arrives there (longer on a loaded machine; a
  // game that never stops fails here), then it plays no more.
  std::uint64_t played = game.played();
  ASSERT_TRUE(until([&] {
    played = game.played();
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
    return game.played() == played;
  })) << "the held game never stopped";
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  frames(2);
  EXPECT_EQ(game.played(), played) << "the game went on while held";
  dbg().command(Command::step);
  ASSERT_TRUE(tvtest::eventually([&] { return game.played() == played + 1; }));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_EQ(game.played(), played + 1) << "a step is one frame";
  ASSERT_TRUE(until([&] { return dbg().currentTick() == live().lastFrame(); }));
  dbg().command(Command::pause);  // go on
  ASSERT_TRUE(tvtest::eventually([&] { return game.played() > played + 10; }));
  game.stop();
}

// A game that does not allow it is never held: the view stops following, the game goes on.
TEST_F(LiveDriver, AGameThatDoesNotAllowControlIsNeverHeld) {  // the control
  const std::string address = listen();
  Recorder rec(gameTo(address, false));
  tvtest::ThreadedGame game(rec);
  ASSERT_TRUE(until([&] { return live().lastFrame() >= 10; }));
  EXPECT_FALSE(live().controllable());
  dbg().command(Command::pause);
  const std::uint64_t played = game.played();
  ASSERT_TRUE(tvtest::eventually([&] { return game.played() > played + 20; }));
  game.stop();
}

// Memory is bounded: past --keep-frames the oldest are dropped, and the window says so.
TEST_F(LiveDriver, TheOldestFramesAreDroppedAndTheWindowSaysSo) {
  const std::string address = listen({"--keep-frames", "40"});
  Recorder rec(gameTo(address, false));
  tvtest::ThreadedGame game(rec);
  ASSERT_TRUE(until([&] { return live().dropped() > 0 && live().lastFrame() > 120; }));
  EXPECT_GT(live().firstFrame(), 0u);
  EXPECT_LE(live().lastFrame() - live().firstFrame(), 120u);
  frames(2);
  const std::string row = drawnText("Timeline");
  EXPECT_NE(row.find("dropped the oldest"), std::string::npos) << row;
  game.stop();
}

// The stream saved is a recording that validates; a game that reconnects starts a new run.
TEST_F(LiveDriver, TheStreamSavedValidatesAndAReconnectIsANewRun) {
  const std::string address = listen();
  {
    Recorder rec(gameTo(address, false));
    tvtest::ThreadedGame game(rec);
    ASSERT_TRUE(until([&] { return live().lastFrame() >= 30; }));
    game.stop();
    rec.close();
  }
  ASSERT_TRUE(until([&] { return live().ended(); }));
  const std::string path = ::testing::TempDir() + "tv_live_saved.tvrec";
  ASSERT_TRUE(dbg().saveStream(path)) << dbg().message();
  Replay saved = Replay::open(path);
  EXPECT_GE(saved.frames(), 30u);
  EXPECT_FALSE(saved.validate().has_value()) << "the saved stream replays bit for bit";
  const std::uint64_t firstRun = live().run();
  Recorder again(gameTo(address, false));
  tvtest::ThreadedGame second(again);
  ASSERT_TRUE(until([&] { return live().run() == firstRun + 1 && live().lastFrame() >= 5; }));
  EXPECT_LT(dbg().currentTick(), 30u) << "the new run starts at its own frame 0";
  second.stop();
}

// The debugger paused on a game that then left (the end of a game pauses it too): the next game
// to connect is a new run, followed as it comes, not held on a frame of its start.
TEST_F(LiveDriver, AGameThatConnectsAfterAPauseIsFollowed) {
  const std::string address = listen();
  {
    Recorder rec(gameTo(address, false));
    tvtest::ThreadedGame game(rec);
    ASSERT_TRUE(until([&] { return live().lastFrame() >= 10; }));
    dbg().command(Command::pause);
    ASSERT_TRUE(dbg().paused());
    game.stop();
    rec.close();
  }
  ASSERT_TRUE(until([&] { return live().ended(); }));
  EXPECT_TRUE(dbg().paused());
  Recorder again(gameTo(address, false));
  tvtest::ThreadedGame second(again);
  ASSERT_TRUE(until([&] { return live().run() == 2 && live().lastFrame() >= 20; }));
  EXPECT_FALSE(dbg().paused());
  EXPECT_TRUE(dbg().followingLive());
  EXPECT_TRUE(until([&] { return dbg().currentTick() >= 20; })) << dbg().currentTick();
  second.stop();
}

// Once the game has left, Space plays back the frames it sent, as a recording's: it answered
// "cannot resume: no game is connected" and the buttons still offered to resume the game.
TEST_F(LiveDriver, AfterTheGameLeavesSpacePlaysBackItsFrames) {
  const std::string address = listen();
  {
    Recorder rec(gameTo(address, true));
    tvtest::ThreadedGame game(rec);
    ASSERT_TRUE(until([&] { return live().lastFrame() >= 40; }));
    game.stop();
    rec.close();
  }
  ASSERT_TRUE(until([&] { return live().ended(); }));
  frames(2);
  const std::string before = drawnText("Timeline");
  EXPECT_EQ(before.find("Resume game"), std::string::npos) << before;
  EXPECT_NE(before.find("Play (Space)"), std::string::npos) << before;
  dbg().command(Command::restart);
  const std::uint64_t first = dbg().currentTick();
  ASSERT_LT(first, live().lastFrame());
  dbg().command(Command::pause);  // Space
  EXPECT_FALSE(dbg().paused());
  frames(10);
  EXPECT_GT(dbg().currentTick(), first) << "the kept frames did not play";
  EXPECT_LT(dbg().currentTick(), live().lastFrame()) << "it jumped to the newest instead";
  EXPECT_TRUE(dbg().message().empty()) << dbg().message();
  dbg().command(Command::step);  // O: the next kept frame, not a step sent to no one
  EXPECT_TRUE(dbg().message().empty()) << dbg().message();
}

// A port already taken is one clear message, and nothing else changes.
TEST_F(LiveDriver, APortInUseIsRefusedNamingIt) {
  LiveReceiverOptions o;
  o.address = "127.0.0.1:0";
  LiveReceiver taken(o);
  open({"--scene", "bullets-wall", "--tick", "1"});
  dbg().tryListen(taken.address());
  EXPECT_NE(dbg().message().find(std::to_string(taken.port())), std::string::npos)
      << dbg().message();
  EXPECT_FALSE(dbg().live());
  EXPECT_EQ(dbg().session().primary().name(), "bullets-wall");
}

}  // namespace
}  // namespace tv::viewer

