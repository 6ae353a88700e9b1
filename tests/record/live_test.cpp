// Specification of the live stream: a game's recorder streams its own chunks to a receiver over
// a loopback socket; the stream saved is a valid recording; the game never waits for a receiver
// that is not there; a receiver may pause and step a game that allows it; a receiver that joins
// late gets a keyframe and the labels; the receiver keeps a bounded window.

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "live_kit.hpp"
#include "recording_kit.hpp"
#include "tv/record/live.hpp"
#include "tv/record/recorder.hpp"
#include "tv/record/replay.hpp"

namespace {

using tvtest::eventually;

tv::LiveOptions liveTo(std::uint16_t port, tvtest::Said* said = nullptr) {
  tv::LiveOptions o;
  o.address = "127.0.0.1:" + std::to_string(port);
  o.retrySeconds = 0.05;
  o.onMessage = said ? said->sink() : [](std::string_view) {};
  return o;
}

tv::LiveReceiverOptions listenAnywhere() {
  tv::LiveReceiverOptions o;
  o.address = "127.0.0.1:0";
  return o;
}

bool has(const std::vector<tv::LiveEvent>& events, tv::LiveEvent::Kind kind,
         const std::string& text = {}) {
  for (const tv::LiveEvent& e : events) {
    if (e.kind == kind && e.text.find(text) != std::string::npos) return true;
  }
  return false;
}

// Collects the receiver's events until `until` holds for one of them (or 10 s pass).
std::vector<tv::LiveEvent> eventsUntil(tv::LiveReceiver& rx, tv::LiveEvent::Kind kind,
                                       const std::string& text = {}) {
  std::vector<tv::LiveEvent> all;
  eventually([&] {
    for (tv::LiveEvent& e : rx.poll()) all.push_back(std::move(e));
    return has(all, kind, text);
  });
  return all;
}

TEST(LiveStream, AStreamSavedFromTheStartIsTheSameFileAsTheRecording) {
  // The scripted game (every kind of call) streams to a receiver that was there before the
  // game attached: what the receiver saves is byte for byte what a recorder writes to memory.
  const std::string path = ::testing::TempDir() + "live_whole.tvrec";
  tv::LiveReceiverOptions ro = listenAnywhere();
  ro.saveTo = path;
  tv::LiveReceiver rx(ro);
  tvtest::Script streamed, recorded;
  {
    tv::Recorder rec(liveTo(rx.port()), tv::RecorderOptions{streamed.keyframeEvery});
    ASSERT_TRUE(eventually([&] { return rec.liveStatus().connected; }));
    streamed.run(rec);
  }  // closed: the end mark goes out
  const auto events = eventsUntil(rx, tv::LiveEvent::Kind::ended);
  EXPECT_TRUE(has(events, tv::LiveEvent::Kind::ended, "closed its recording"))
      << events.back().text;
  const std::vector<std::uint8_t> expected = recorded.record();
  EXPECT_EQ(tvtest::readFile(path), expected);
  EXPECT_EQ(rx.file(), expected);
  tv::Replay r = tv::Replay::open(path);
  EXPECT_FALSE(r.validate());
  EXPECT_TRUE(r.warnings().empty());
}

TEST(LiveStream, AReceiverThatJoinsMidGameGetsAKeyframeAndTheLabelsOfWhatIsInTheWorld) {
  // Nobody listens for the first frames (the game copies nothing then); a receiver comes; its
  // run begins at a keyframe with the player's label repeated, and the saved run replays.
  const std::uint16_t port = tvtest::freePort();
  tv::Recorder rec(liveTo(port));
  tv::World world(16);
  world.add({0, 40, 400, 8});  // floor
  world.attach(rec);
  const tv::ItemId player = world.add({0, 20, 8, 16});
  rec.label(player, "player", "player");
  tv::Mover mover{tv::MoverSpec{}};
  const auto play = [&](int frames) {
    for (int f = 0; f < frames; ++f) {
      (void)mover.move(world, player, world.rect(player).position() + tv::Vec2{1.5, 3});
      rec.frame();
    }
  };
  play(20);
  EXPECT_EQ(rec.calls(), 0u);  // nobody listened: nothing was copied
  tv::LiveReceiverOptions ro = listenAnywhere();
  ro.address = "127.0.0.1:" + std::to_string(port);
  tv::LiveReceiver rx(ro);
  ASSERT_TRUE(eventually([&] { return rec.liveStatus().connected; }));
  play(30);
  ASSERT_TRUE(eventually([&] { return rx.window().nextFrame >= 25; }));
  const tv::LiveWindow w = rx.window();
  ASSERT_FALSE(w.frames.empty());
  EXPECT_TRUE(w.frames.front()->keyframe);
  tv::Replay r = tv::Replay::fromBytes(rx.file());
  EXPECT_EQ(r.label(player), "player");
  const auto d = r.validate();
  EXPECT_FALSE(d) << d->report();
}

TEST(LiveStream, NegativeControlARecordingCutAtAKeyframeWithoutItsLabelsForgetsTheirNames) {
  // What the repeated labels are for: the same game recorded whole, cut at frame 20's
  // keyframe and renumbered, knows the player only as "item 1.0".
  tv::Recorder rec(tv::RecorderOptions{4});
  tv::World world(16);
  world.add({0, 40, 400, 8});
  world.attach(rec);
  const tv::ItemId player = world.add({0, 20, 8, 16});
  rec.label(player, "player", "player");
  for (int f = 0; f < 30; ++f) {
    (void)world.move(player, world.rect(player).position() + tv::Vec2{1.5, 3});
    rec.frame();
  }
  rec.close();
  const std::vector<std::size_t> starts = tvtest::chunks(rec.bytes());
  std::vector<std::uint8_t> cut(rec.bytes().begin(), rec.bytes().begin() + 32);
  for (std::size_t k = 20; k < starts.size(); ++k) {
    tvtest::appendRenumbered(cut, rec.bytes(), starts[k], k - 20);
  }
  tv::Replay r = tv::Replay::fromBytes(cut);
  EXPECT_EQ(r.label(player), "item 1.0");
}

TEST(LiveStream, NobodyListeningIsSaidOnceAndTheGameRunsOnWithoutCopyingAnything) {
  tvtest::Said said;
  tv::LiveOptions o = liveTo(tvtest::freePort(), &said);
  tv::Recorder rec(o);
  tv::World world(16);
  world.attach(rec);
  const tv::ItemId a = world.add({0, 0, 4, 4});
  const auto start = std::chrono::steady_clock::now();
  std::uint64_t frames = 0;
  while (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(400)) {
    (void)world.move(a, world.rect(a).position() + tv::Vec2{1, 0});
    rec.frame();
    ++frames;
  }
  rec.close();               // the message thread is done
  EXPECT_GT(frames, 1000u);  // never held up
  EXPECT_EQ(rec.calls(), 0u);
  const std::vector<std::string> lines = said.lines();
  ASSERT_EQ(lines.size(), 1u);  // tried every 50 ms, said once
  EXPECT_NE(lines[0].find("connection refused"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("the game goes on"), std::string::npos) << lines[0];
}

TEST(LiveStream, APortInUseIsRefusedWithTheAddressAndTheReason) {
  tv::LiveReceiver first(listenAnywhere());
  tv::LiveReceiverOptions o;
  o.address = first.address();
  try {
    tv::LiveReceiver second(o);
    FAIL() << "no error";
  } catch (const tv::Error& e) {
    EXPECT_NE(std::string(e.what()).find(first.address() + " is in use"), std::string::npos)
        << e.what();
  }
}

TEST(LiveStream, AMalformedAddressIsRefusedNamingIt) {
  tv::LiveOptions o;
  o.address = "localhost:port";
  EXPECT_THROW((tv::Recorder(o)), tv::Error);
  try {
    tv::Recorder r(o);
  } catch (const tv::Error& e) {
    EXPECT_NE(std::string(e.what()).find("'localhost:port' has no port number"), std::string::npos)
        << e.what();
  }
}

TEST(LiveStream, PauseHoldsTheGameAtItsFrameMarkStepLetsOneFramePassResumeLetsItGo) {
  auto rx = std::make_unique<tv::LiveReceiver>(listenAnywhere());
  tv::LiveOptions o = liveTo(rx->port());
  o.control = true;
  tv::Recorder rec(o);
  tvtest::ThreadedGame game(rec);
  // Whatever fails below, the receiver goes first: a game it holds is let go.
  struct LetGo {
    std::unique_ptr<tv::LiveReceiver>& rx;
    ~LetGo() { rx.reset(); }
  } letGo{rx};
  ASSERT_TRUE(eventually([&] { return rx->window().nextFrame > 5; }));
  EXPECT_TRUE(rx->window().controllable);
  ASSERT_TRUE(rx->pause());
  // Held: at most the frame being played when the pause came passes, then nothing, neither in
  // the game nor on the wire.
  const auto settled = [&] {
    const std::uint64_t played = game.played(), received = rx->window().nextFrame;
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    return game.played() == played && rx->window().nextFrame == received;
  };
  ASSERT_TRUE(eventually(settled));
  const std::uint64_t held = game.played(), received = rx->window().nextFrame;
  ASSERT_TRUE(rx->step());
  ASSERT_TRUE(eventually([&] { return game.played() == held + 1; }));
  ASSERT_TRUE(eventually([&] { return rx->window().nextFrame == received + 1; }));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_EQ(game.played(), held + 1);  // one frame, then held again
  EXPECT_EQ(rx->window().nextFrame, received + 1);
  ASSERT_TRUE(rx->resume());
  EXPECT_TRUE(eventually([&] { return game.played() > held + 20; }));
  game.stop();
}

TEST(LiveStream, NegativeControlAGameThatDoesNotAllowControlIsNeverHeld) {
  tv::LiveReceiver rx(listenAnywhere());
  tv::Recorder rec(liveTo(rx.port()));  // control off
  tvtest::ThreadedGame game(rec);
  ASSERT_TRUE(eventually([&] { return rx.window().nextFrame > 5; }));
  EXPECT_FALSE(rx.window().controllable);
  EXPECT_FALSE(rx.pause());
  EXPECT_TRUE(has(rx.poll(), tv::LiveEvent::Kind::control, "does not accept pause"));
  const std::uint64_t before = game.played();
  EXPECT_TRUE(eventually([&] { return game.played() > before + 20; }));
  game.stop();
}

TEST(LiveStream, AGameThatIsDisconnectedConnectsAgainAsANewRun) {
  tv::LiveReceiver rx(listenAnywhere());
  tv::Recorder rec(liveTo(rx.port()));
  tvtest::ThreadedGame game(rec);
  ASSERT_TRUE(eventually([&] { return rx.window().run == 1 && rx.window().nextFrame > 5; }));
  rx.disconnect();
  ASSERT_TRUE(eventually([&] { return rx.window().run == 2 && rx.window().nextFrame > 5; }));
  const tv::LiveWindow w = rx.window();
  EXPECT_TRUE(w.frames.front()->keyframe);
  EXPECT_EQ(w.frames.front()->number, 0u);
  game.stop();
  tv::Replay r = tv::Replay::fromBytes(rx.file());
  EXPECT_EQ(r.label(game.first()), "walker 0");
  EXPECT_FALSE(r.validate());
}

TEST(LiveStream, TheReceiverKeepsABoundedWindowThatStartsAtAKeyframeAndSaysWhatItDropped) {
  tv::LiveReceiverOptions ro = listenAnywhere();
  ro.keepFrames = 40;
  tv::LiveReceiver rx(ro);
  tv::Recorder rec(liveTo(rx.port()), tv::RecorderOptions{16});
  tvtest::ThreadedGame game(rec);
  ASSERT_TRUE(eventually([&] { return rx.window().nextFrame > 150; }));
  game.stop();
  const auto events = eventsUntil(rx, tv::LiveEvent::Kind::dropped);
  EXPECT_TRUE(has(events, tv::LiveEvent::Kind::dropped, "dropped the oldest"));
  const tv::LiveWindow w = rx.window();
  EXPECT_LE(w.frames.size(), 40u);
  EXPECT_GT(w.dropped, 100u);
  EXPECT_EQ(w.firstKept + w.frames.size(), w.nextFrame);
  EXPECT_TRUE(w.frames.front()->keyframe);
  tv::Replay r = tv::Replay::fromBytes(rx.file());
  EXPECT_FALSE(r.validate());
}

TEST(LiveStream, ASecondGameIsRefusedWhileOneIsConnected) {
  tv::LiveReceiver rx(listenAnywhere());
  tv::Recorder rec(liveTo(rx.port()));
  tvtest::ThreadedGame game(rec);
  ASSERT_TRUE(eventually([&] { return rx.window().nextFrame > 2; }));
  tvtest::RawPeer second(rx.port());
  ASSERT_TRUE(second.connected());
  EXPECT_TRUE(second.closedByTheOtherSide());
  EXPECT_TRUE(has(eventsUntil(rx, tv::LiveEvent::Kind::refused), tv::LiveEvent::Kind::refused,
                  "refused a second game"));
  EXPECT_TRUE(rx.window().connected);  // the first one goes on
  game.stop();
}

TEST(LiveStream, AReceiverThatDoesNotReadIsDroppedAndTheGameGoesOn) {
  // A listener that accepts, answers, and then never reads: the game's queue reaches its
  // bound (1 MiB) and the game disconnects it rather than wait.
  const int server = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(server, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
  ASSERT_EQ(::listen(server, 1), 0);
  socklen_t len = sizeof a;
  getsockname(server, reinterpret_cast<sockaddr*>(&a), &len);
  tvtest::Said said;
  tv::LiveOptions o = liveTo(ntohs(a.sin_port), &said);
  o.maxPendingBytes = 1 << 20;
  o.retrySeconds = 60;  // once is enough here
  tv::Recorder rec(o);
  const int peer = ::accept(server, nullptr, nullptr);
  const std::uint8_t reply[8] = {'T', 'V', 'L', 'I', 'V', 'E', 'C', 1};
  ASSERT_EQ(::send(peer, reply, 8, 0), 8);
  {
    tvtest::ThreadedGame game(rec, 2000);
    ASSERT_TRUE(eventually([&] { return said.contains("fell more than 1 MiB behind"); }));
    const std::uint64_t before = game.played();
    EXPECT_TRUE(eventually([&] { return game.played() > before + 10; }));
  }
  ::close(peer);
  ::close(server);
}

}  // namespace
