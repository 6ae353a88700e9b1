// tv-example-platformer: a small platformer that records itself — what a game adds to be
// debugged with Tunnelvision (look for "recording" below: about ten lines).
//
// A player runs along a floor of 16 px tiles (a seam every tile), jumps onto a ledge, falls off
// it, and shoots 4 px bullets at 1920 px/s at a wall 2 px thin. Input is scripted by frame
// number, the loop runs on a FixedStep with a frame time that hitches now and then, and nothing
// is drawn: it runs headless, as fast as it can.
//
// With --live HOST:PORT it also streams itself to a receiver (tv-replay --listen, or a debugger
// built on tv::LiveReceiver) as it plays, at the pace of real time so that a person can watch; the
// debugger may pause it and step it a frame at a time.
//
// By default every body moves with tv's `continuous` mover. `--naive` moves them the way many
// games do — x += v·dt, update, push out of whatever it overlaps — so its bullets pass through
// the wall; `tv-replay FILE --mover continuous --updates-as-moves` then shows what the fix does.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "tv/app/flags.hpp"
#include "tv/app/platformer_game.hpp"
#include "tv/app/user_message.hpp"
#include "tv/mover.hpp"
#include "tv/record/live.hpp"
#include "tv/record/recorder.hpp"
#include "tv/timestep.hpp"
#include "tv/world.hpp"

namespace {

struct UsageError {
  std::string message;
};

struct Options {
  std::uint64_t frames = 600;
  std::string record;
  std::string live;
  bool naive = false;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view a = argv[i];
    const auto value = [&]() -> std::string_view {
      if (i + 1 >= argc) throw UsageError{std::string(a) + " needs a value"};
      return argv[++i];
    };
    if (a == "--frames") {
      o.frames = tv::app::parseWhole<UsageError>("frames", value());
      if (o.frames == 0 || o.frames > 100000000) throw UsageError{"--frames: expected 1 to 10^8"};
    } else if (a == "--record") {
      o.record = value();
    } else if (a == "--live") {
      o.live = value();
    } else if (a == "--naive") {
      o.naive = true;
    } else if (a == "--help" || a == "-h") {
      std::cout
          << "usage: tv-example-platformer [--frames N] [--record FILE] [--live HOST:PORT] "
             "[--naive]\n"
             "  --frames N     rendered frames to play (default 600)\n"
             "  --record FILE  record the game into FILE (.tvrec) for tv-replay\n"
             "  --live HOST:PORT  stream the game to a debugger listening there (PORT alone:\n"
             "                 127.0.0.1), at the pace of real time; it may pause and step it\n"
             "  --naive        move bodies by x += v*dt, update, push out (they tunnel)\n";
      std::exit(0);
    } else {
      throw UsageError{"unknown flag '" + std::string(a) + "' (try --help)"};
    }
  }
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  try {
    o = parse(argc, argv);
  } catch (const UsageError& e) {
    std::cerr << "tv-example-platformer: " << e.message << "\n";
    return 2;
  }
  tv::example::Game game(o.naive);
  tv::FixedStep step(1.0 / 60.0);

  // -- recording: a Recorder attached to the world, frames from the FixedStep -----------------
  std::optional<tv::Recorder> recorder;
  std::optional<tv::LiveOptions> live;
  if (!o.live.empty()) {
    live.emplace();
    live->address = o.live;
    live->control = true;  // the debugger may pause the game at its frame marks
  }
  if (!o.record.empty() || live) {
    try {
      if (o.record.empty()) {
        recorder.emplace(*live);  // streams only: nothing is copied while nobody listens
      } else {
        recorder.emplace(o.record);
        if (live) recorder->stream(*live);
      }
      game.world().attach(*recorder);
      recorder->attach(step);
    } catch (const tv::Error& e) {
      // An unwritable path or a malformed address: what was asked for cannot be made, so stop
      // before playing (a script waiting on the file must not see success).
      std::cerr << "tv-example-platformer: "
                << (live && o.record.empty() ? "--live " + o.live : "--record " + o.record) << ": "
                << tv::app::userMessage(e) << "\n";
      return 1;
    }
  }
  tv::Recorder* rec = recorder ? &*recorder : nullptr;
  if (live) {
    // The stream connects on a thread of its own: give it its first try before the first frame
    // (at most 2 s), so that a short game run beside a listening receiver is seen from frame 0
    // even on a loaded machine. Nobody listening: it says so and the game plays on.
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    for (;;) {
      const tv::LiveStatus s = recorder->liveStatus();
      if (s.connected || !s.message.empty() || std::chrono::steady_clock::now() > until) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
  // -------------------------------------------------------------------------------------------

  game.build(rec);
  auto due = std::chrono::steady_clock::now();
  for (std::uint64_t frame = 0; frame < o.frames; ++frame) {
    const double frameTime = frame % 7 == 3 ? 1.0 / 30.0 : 1.0 / 60.0;  // a hitch now and then
    if (live) {  // watched live: the frames come at the pace they claim
      due += std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(frameTime));
      std::this_thread::sleep_until(due);
    }
    const int ticks = step.advance(frameTime);  // a paused debugger holds the game here
    if (live) due = std::max(due, std::chrono::steady_clock::now());
    for (int t = 0; t < ticks; ++t) game.tick(game.ticks++, step.step(), rec);
  }
  std::printf("ticks: %llu · bullets fired: %d, stopped by the wall: %d, through the wall: %d\n",
              static_cast<unsigned long long>(game.ticks), game.fired(), game.stopped(),
              game.through());
  if (recorder) {
    recorder->close();
    if (!recorder->ok()) {
      std::cerr << "tv-example-platformer: " << recorder->error() << "\n";
      return 1;
    }
    if (!o.record.empty()) {
      std::printf("recorded %llu frames, %llu moves, %llu bytes into %s\n",
                  static_cast<unsigned long long>(recorder->frames()),
                  static_cast<unsigned long long>(recorder->moves()),
                  static_cast<unsigned long long>(recorder->size()), o.record.c_str());
    }
  }
  return 0;
}
