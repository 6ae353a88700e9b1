// A LÖVE game watched live with no code (TV_LIVE) is held by its receiver as the C++ sample is:
// pause stops it at LÖVE's next frame mark, step lets one frame pass, resume lets it go on. The
// game (tests/lua/love/live_pause) prints each frame's number; the test reads them.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "tv/record/live.hpp"
#include "tv/record/replay.hpp"

namespace {

using Clock = std::chrono::steady_clock;

// Waits until `ok()` holds or `seconds` pass; returns whether it held.
template <class F>
bool within(double seconds, F ok) {
  const auto end = Clock::now() + std::chrono::duration<double>(seconds);
  while (Clock::now() < end) {
    if (ok()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return ok();
}

// The game, started with TV_LIVE pointing at `port`; `played` is the last frame it printed.
class Game {
 public:
  Game(std::uint16_t port, int frames) {
    const std::string command = "TV_LIVE=127.0.0.1:" + std::to_string(port) +
                                " TV_LUA_MODULE_DIR='" TV_TEST_LUA_MODULE_DIR
                                "' SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy '" TV_TEST_LOVE
                                "' '" TV_TEST_GAME "' " + std::to_string(frames) + " 2>/dev/null";
    pipe_ = popen(command.c_str(), "r");
    reader_ = std::thread([this] {
      char line[256];
      while (pipe_ != nullptr && std::fgets(line, sizeof line, pipe_) != nullptr) {
        int n = 0;
        if (std::sscanf(line, "frame %d", &n) == 1) played.store(n);
      }
    });
  }
  ~Game() { (void)finish(); }
  Game(const Game&) = delete;
  Game& operator=(const Game&) = delete;
  // Waits for the game to end; its exit status.
  int finish() {
    if (reader_.joinable()) reader_.join();
    if (pipe_ == nullptr) return -1;
    const int status = pclose(pipe_);
    pipe_ = nullptr;
    return status;
  }
  std::atomic<int> played{0};

 private:
  std::FILE* pipe_ = nullptr;
  std::thread reader_;
};

TEST(LoveLive, PauseHoldsTheGameAtItsFrameMarkStepLetsOneFramePassResumeLetsItFinish) {
  tv::LiveReceiverOptions listen;
  listen.address = "127.0.0.1:0";
  tv::LiveReceiver rx(listen);
  Game game(rx.port(), 400);
  ASSERT_TRUE(within(30, [&] { return rx.window().connected && game.played.load() >= 10; }))
      << "the game did not connect (TV_LIVE) or play 10 frames";
  EXPECT_TRUE(rx.window().controllable);  // TV_LIVE games accept pause and step
  // Before the pause the game moves on: what the test reads would see a held game.
  const int before = game.played.load();
  ASSERT_TRUE(within(5, [&] { return game.played.load() > before + 5; }));

  ASSERT_TRUE(rx.pause());
  // The pause reaches the game within a frame or two (longer on a loaded machine): wait until
  // it stops, then nothing more for a second. A game that never stops fails here.
  int held = game.played.load();
  ASSERT_TRUE(within(20, [&] {
    held = game.played.load();
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
    return game.played.load() == held;
  })) << "the paused game never stopped";
  std::this_thread::sleep_for(std::chrono::seconds(1));
  EXPECT_EQ(game.played.load(), held) << "the paused game went on playing";
  EXPECT_LT(held, 400);

  ASSERT_TRUE(rx.step());
  EXPECT_TRUE(within(5, [&] { return game.played.load() == held + 1; }));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  EXPECT_EQ(game.played.load(), held + 1) << "a step let more than one frame pass";

  ASSERT_TRUE(rx.resume());
  EXPECT_EQ(game.finish(), 0);
  EXPECT_EQ(game.played.load(), 400);
  ASSERT_TRUE(within(10, [&] { return rx.window().closed; }));
  // What was kept replays as the game played it, traced too.
  tv::Replay replay = tv::Replay::fromBytes(rx.file());
  EXPECT_FALSE(replay.validate({}, tv::Replay::Tracing::on).has_value());
}

}  // namespace
