#pragma once
// Keeping the frames a game handed over when it dies. A recorder's writer writes each frame on
// its own thread; if the game crashes (a fault, abort, an uncaught exception) or calls exit()
// with a recorder still open, the process would take the frames still in flight with it. While
// a recorder writing to a file is open, these paths wait — a bounded time — for its writer to
// write and flush every frame handed over, then let the process die as it would have.
//
// On POSIX systems (Linux, macOS):
//   - fatal signals SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT (abort, failed asserts), and SIGINT,
//     SIGTERM, SIGHUP — each only when its action was the default one (a game's own handler,
//     or a sanitizer's, is left alone); sigaction, then the signal raised again;
//   - std::terminate (uncaught exceptions), chained to the handler before it;
//   - exit() (an atexit handler).
// On Windows:
//   - the C signals the C runtime has (std::signal): SIGSEGV, SIGFPE, SIGILL, SIGABRT (abort,
//     failed asserts), SIGINT (Ctrl+C in a console), SIGTERM (raised by the program itself:
//     Windows sends none) — each only when its handler was SIG_DFL; there is no SIGBUS or SIGHUP;
//   - faults the C runtime does not turn into signals — an access violation, a stack overflow,
//     an illegal instruction, a division by zero in a thread of the game's own, a fault in a
//     DLL such as the Lua module inside love.exe — through SetUnhandledExceptionFilter, chained
//     to the filter before it. Not when a debugger is attached (it sees the fault first), nor
//     if the game or a library sets a filter of its own later (the last one set wins);
//   - the console closing, the user logging off, the system shutting down (a console control
//     handler: Windows ends the process about 5 s later anyway);
//   - std::terminate, chained; exit() (atexit), except that when tv::record is inside a DLL its
//     atexit handler runs only as the DLL unloads, after Windows has already ended every other
//     thread — the writer included, so nothing is waited for there (the game's own exit path,
//     a recorder closed or destroyed, keeps every frame; Recorder::close before exit).
// Not covered anywhere: SIGKILL or TerminateProcess, _exit/quick_exit, a crash of the writer's
// own thread, a writer that is itself stuck (a heap so corrupt that allocation hangs: the wait
// gives up after 2 s), a frame not yet handed over (the one being played), and the end mark
// (such a file replays with a warning that the game did not close it).

#include <atomic>
#include <cstdint>
#include <thread>

namespace tv::rec {

struct CrashWatch {
  std::atomic<std::uint64_t> handed{0};                 // frames handed over (game's thread)
  const std::atomic<std::uint64_t>* written = nullptr;  // frames written and flushed (writer)
  std::thread::id writer;                               // not to be waited for by itself
  // Windows: the writer's system thread id (0 until it runs): a writer that no longer runs
  // (ended by the system as the process exits) is not waited for.
  const std::atomic<std::uint32_t>* writerSystemId = nullptr;
};

// The handlers are installed while at least one recorder is watched and removed — the ones
// before put back, unless someone replaced ours since — when the last is unwatched, so that no
// handler points into a library that was unloaded (the Lua module, when its Lua state closes).
// `w` must stay valid until unwatch(w).
void watchForCrash(CrashWatch* w);
void unwatch(CrashWatch* w);

// The calling thread's id as the system numbers it (Windows: GetCurrentThreadId; 0 elsewhere,
// where it is not needed).
std::uint32_t systemThreadId();

}  // namespace tv::rec
