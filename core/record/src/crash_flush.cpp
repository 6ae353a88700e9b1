// The crash flush (crash_flush.hpp). The signal handler only reads atomics and sleeps
// (clock_gettime, nanosleep, sigaction and raise are async-signal-safe); the writing is done by
// the writer's thread, which is not interrupted.

#include "crash_flush.hpp"

#include <csignal>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <mutex>

namespace tv::rec {
namespace {

constexpr int kSlots = 64;
std::atomic<CrashWatch*> gWatched[kSlots];

constexpr int kSignals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGINT, SIGTERM, SIGHUP};
struct sigaction gPrevious[sizeof kSignals / sizeof kSignals[0]];
std::terminate_handler gPreviousTerminate = nullptr;

double now() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

// Waits until every watched writer has written what was handed to it, or `seconds` pass.
void waitForWriters(double seconds) {
  const double deadline = now() + seconds;
  const std::thread::id self = std::this_thread::get_id();
  for (std::atomic<CrashWatch*>& slot : gWatched) {
    const CrashWatch* w = slot.load(std::memory_order_acquire);
    if (!w || !w->written || w->writer == self) continue;
    while (w->written->load(std::memory_order_acquire) <
               w->handed.load(std::memory_order_acquire) &&
           now() < deadline) {
      const timespec ms{0, 1000000};
      nanosleep(&ms, nullptr);
    }
  }
}

void onSignal(int sig) {
  waitForWriters(2.0);
  for (std::size_t i = 0; i < sizeof kSignals / sizeof kSignals[0]; ++i) {
    if (kSignals[i] == sig) sigaction(sig, &gPrevious[i], nullptr);
  }
  // Blocked until this handler returns, then delivered with the previous (default) action; a
  // fault also recurs when its instruction runs again.
  raise(sig);
}

void onTerminate() {
  waitForWriters(2.0);
  if (gPreviousTerminate) gPreviousTerminate();
  std::abort();
}

void onExit() {
  waitForWriters(5.0);
}

void install() {
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
    sigaction(kSignals[i], &ours, nullptr);
  }
  gPreviousTerminate = std::set_terminate(&onTerminate);
  std::atexit(&onExit);
}

}  // namespace

void watchForCrash(CrashWatch* w) {
  static std::once_flag once;
  std::call_once(once, install);
  for (std::atomic<CrashWatch*>& slot : gWatched) {
    CrashWatch* expected = nullptr;
    if (slot.compare_exchange_strong(expected, w, std::memory_order_acq_rel)) return;
  }
  // More than 64 recorders open at once: the others are not waited for.
}

void unwatch(CrashWatch* w) {
  for (std::atomic<CrashWatch*>& slot : gWatched) {
    CrashWatch* expected = w;
    if (slot.compare_exchange_strong(expected, nullptr, std::memory_order_acq_rel)) return;
  }
}

}  // namespace tv::rec
