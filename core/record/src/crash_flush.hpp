#pragma once
// Keeping the frames a game handed over when it dies. A recorder's writer writes each frame on
// its own thread; if the game crashes (a fault, abort, an uncaught exception) or calls exit()
// with a recorder still open, the process would take the frames still in flight with it. While
// a recorder writing to a file is open, these paths wait — a bounded time — for its writer to
// write and flush every frame handed over, then let the process die as it would have:
//   - fatal signals SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT (abort, failed asserts), and SIGINT,
//     SIGTERM, SIGHUP — each only when its action was the default one (a game's own handler,
//     or a sanitizer's, is left alone);
//   - std::terminate (uncaught exceptions), chained to the handler before it;
//   - exit() (an atexit handler).
// Not covered: SIGKILL, _exit/quick_exit, a crash of the writer's own thread, a writer that is
// itself stuck (a heap so corrupt that allocation hangs: the wait gives up after 2 s), a frame
// not yet handed over (the one being played), and the end mark (such a file replays with a
// warning that the game did not close it).

#include <atomic>
#include <cstdint>
#include <thread>

namespace tv::rec {

struct CrashWatch {
  std::atomic<std::uint64_t> handed{0};                 // frames handed over (game's thread)
  const std::atomic<std::uint64_t>* written = nullptr;  // frames written and flushed (writer)
  std::thread::id writer;                               // not to be waited for by itself
};

// Installs the handlers the first time; `w` must stay valid until unwatch(w).
void watchForCrash(CrashWatch* w);
void unwatch(CrashWatch* w);

}  // namespace tv::rec
