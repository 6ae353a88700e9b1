// The crash flush (crash_flush.hpp). A handler only reads atomics and sleeps (on POSIX systems
// clock_gettime, nanosleep, sigaction and raise are async-signal-safe); the writing is done by
// the writer's thread, which is not interrupted.
//
// Index: [SECTION] waiting · [SECTION] POSIX systems · [SECTION] Windows · [SECTION] watching

#include "crash_flush.hpp"

#include <csignal>
#include <cstdlib>
#include <exception>
#include <mutex>

#ifdef _WIN32
#include <windows.h>
#else
#include <ctime>
#endif

namespace tv::rec {
namespace {

constexpr int kSlots = 64;
std::atomic<CrashWatch*> gWatched[kSlots];
std::terminate_handler gPreviousTerminate = nullptr;
// The handlers are in place while a recorder is watched, and no longer: the code they point to
// may be unloaded with the library (the Lua module, when its Lua state closes).
std::mutex gInstallLock;
int gWatchers = 0;
bool gExitHooked = false;

// [SECTION] waiting ----------------------------------------------------------------------------

#ifdef _WIN32
double now() {
  return static_cast<double>(GetTickCount64()) * 1e-3;
}
void sleepAMillisecond() {
  Sleep(1);
}
// False when the writer's thread has ended (Windows ends every other thread before a DLL's
// atexit handlers run) or is not known to the system any more.
bool running(const CrashWatch& w) {
  const std::uint32_t id = w.writerSystemId ? w.writerSystemId->load(std::memory_order_acquire) : 0;
  if (id == 0) return true;  // not started yet: it will run
  HANDLE h = OpenThread(SYNCHRONIZE, FALSE, id);
  if (h == nullptr) return false;
  const bool ended = WaitForSingleObject(h, 0) == WAIT_OBJECT_0;
  CloseHandle(h);
  return !ended;
}
#else
double now() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}
void sleepAMillisecond() {
  const timespec ms{0, 1000000};
  nanosleep(&ms, nullptr);
}
bool running(const CrashWatch&) {
  return true;  // exit() runs atexit handlers while every thread still runs
}
#endif

// Waits until every watched writer has written what was handed to it, or `seconds` pass.
void waitForWriters(double seconds) {
  const double deadline = now() + seconds;
  const std::thread::id self = std::this_thread::get_id();
  for (std::atomic<CrashWatch*>& slot : gWatched) {
    const CrashWatch* w = slot.load(std::memory_order_acquire);
    if (!w || !w->written || w->writer == self || !running(*w)) continue;
    while (w->written->load(std::memory_order_acquire) <
               w->handed.load(std::memory_order_acquire) &&
           now() < deadline) {
      sleepAMillisecond();
    }
  }
}

void onTerminate() {
  waitForWriters(2.0);
  if (gPreviousTerminate) gPreviousTerminate();
  std::abort();
}

void onExit() {
  waitForWriters(5.0);
}

#ifndef _WIN32
// [SECTION] POSIX systems ----------------------------------------------------------------------

constexpr int kSignals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGINT, SIGTERM, SIGHUP};
struct sigaction gPrevious[sizeof kSignals / sizeof kSignals[0]];
bool gOurs[sizeof kSignals / sizeof kSignals[0]];

void onSignal(int sig) {
  waitForWriters(2.0);
  for (std::size_t i = 0; i < sizeof kSignals / sizeof kSignals[0]; ++i) {
    if (kSignals[i] == sig) sigaction(sig, &gPrevious[i], nullptr);
  }
  // Blocked until this handler returns, then delivered with the previous (default) action; a
  // fault also recurs when its instruction runs again.
  raise(sig);
}

void installSystemHandlers() {
  for (std::size_t i = 0; i < sizeof kSignals / sizeof kSignals[0]; ++i) {
    struct sigaction current {};
    if (sigaction(kSignals[i], nullptr, &current) != 0) continue;
    // The game's own handler, a sanitizer's, or an ignored signal: left as it is.
    if ((current.sa_flags & SA_SIGINFO) != 0 || current.sa_handler != SIG_DFL) continue;
    gPrevious[i] = current;
    struct sigaction ours {};
    ours.sa_handler = &onSignal;
    sigemptyset(&ours.sa_mask);
    ours.sa_flags = SA_RESTART;
    gOurs[i] = sigaction(kSignals[i], &ours, nullptr) == 0;
  }
}

void removeSystemHandlers() {
  for (std::size_t i = 0; i < sizeof kSignals / sizeof kSignals[0]; ++i) {
    if (!gOurs[i]) continue;
    gOurs[i] = false;
    struct sigaction current {};
    // Set by someone else since: theirs now, left alone.
    if (sigaction(kSignals[i], nullptr, &current) != 0 || (current.sa_flags & SA_SIGINFO) != 0 ||
        current.sa_handler != &onSignal) {
      continue;
    }
    sigaction(kSignals[i], &gPrevious[i], nullptr);
  }
}

#else
// [SECTION] Windows ----------------------------------------------------------------------------

constexpr int kSignals[] = {SIGSEGV, SIGFPE, SIGILL, SIGABRT, SIGINT, SIGTERM};
bool gOurs[sizeof kSignals / sizeof kSignals[0]];
LPTOP_LEVEL_EXCEPTION_FILTER gPreviousFilter = nullptr;

void onSignal(int sig) {
  waitForWriters(2.0);
  // The C runtime has put SIG_DFL back before calling us (for all but SIGFPE, which it leaves):
  // raised again, the signal ends the process as it would have.
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

LONG WINAPI onUnhandledException(EXCEPTION_POINTERS* e) {
  waitForWriters(2.0);
  return gPreviousFilter ? gPreviousFilter(e) : EXCEPTION_CONTINUE_SEARCH;
}

BOOL WINAPI onConsoleEnd(DWORD event) {
  if (event == CTRL_CLOSE_EVENT || event == CTRL_LOGOFF_EVENT || event == CTRL_SHUTDOWN_EVENT) {
    waitForWriters(2.0);
  }
  return FALSE;  // the next handler (in the end, the system's: the process ends)
}

void installSystemHandlers() {
  for (std::size_t i = 0; i < sizeof kSignals / sizeof kSignals[0]; ++i) {
    const auto previous = std::signal(kSignals[i], &onSignal);
    gOurs[i] = previous == SIG_DFL;
    // The game's own handler, or an ignored signal: put back and left alone.
    if (previous != SIG_DFL && previous != SIG_ERR) std::signal(kSignals[i], previous);
  }
  gPreviousFilter = SetUnhandledExceptionFilter(&onUnhandledException);
  SetConsoleCtrlHandler(&onConsoleEnd, TRUE);  // harmless without a console
}

void removeSystemHandlers() {
  for (std::size_t i = 0; i < sizeof kSignals / sizeof kSignals[0]; ++i) {
    if (!gOurs[i]) continue;
    gOurs[i] = false;
    const auto current = std::signal(kSignals[i], SIG_DFL);
    if (current != &onSignal && current != SIG_ERR) std::signal(kSignals[i], current);  // theirs
  }
  const LPTOP_LEVEL_EXCEPTION_FILTER current = SetUnhandledExceptionFilter(gPreviousFilter);
  if (current != &onUnhandledException) SetUnhandledExceptionFilter(current);  // theirs
  SetConsoleCtrlHandler(&onConsoleEnd, FALSE);
}
#endif

void install() {
  installSystemHandlers();
  gPreviousTerminate = std::set_terminate(&onTerminate);
  // An atexit handler cannot be removed; it waits for no one once nothing is watched. (In a
  // shared library, the C runtime runs it when the library unloads.)
  if (!gExitHooked) std::atexit(&onExit);
  gExitHooked = true;
}

void uninstall() {
  removeSystemHandlers();
  if (std::get_terminate() == &onTerminate) std::set_terminate(gPreviousTerminate);
}

}  // namespace

// [SECTION] watching ---------------------------------------------------------------------------

void watchForCrash(CrashWatch* w) {
  {
    std::lock_guard lock(gInstallLock);
    if (gWatchers++ == 0) install();
  }
  for (std::atomic<CrashWatch*>& slot : gWatched) {
    CrashWatch* expected = nullptr;
    if (slot.compare_exchange_strong(expected, w, std::memory_order_acq_rel)) return;
  }
  // More than 64 recorders open at once: the others are not waited for.
}

void unwatch(CrashWatch* w) {
  for (std::atomic<CrashWatch*>& slot : gWatched) {
    CrashWatch* expected = w;
    if (slot.compare_exchange_strong(expected, nullptr, std::memory_order_acq_rel)) break;
  }
  std::lock_guard lock(gInstallLock);
  if (gWatchers > 0 && --gWatchers == 0) uninstall();
}

std::uint32_t systemThreadId() {
#ifdef _WIN32
  return static_cast<std::uint32_t>(GetCurrentThreadId());
#else
  return 0;
#endif
}

}  // namespace tv::rec
