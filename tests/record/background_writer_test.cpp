// Specification of the recorder's writer thread: the game's thread only copies each call into
// memory; another thread encodes and writes. What must hold:
//   - the bytes are exactly those written on the game's thread (RecorderOptions::background off);
//   - a game faster than its writer waits at the queue's bound instead of filling memory;
//   - a game that dies — a fault, abort, an uncaught exception, exit() — leaves every frame it
//     handed over in the file (and the negative control: without the crash flush, a frame handed
//     over a moment before the crash is lost);
//   - the crash handlers are there only while a file recorder is open, and a handler the game
//     sets meanwhile is its own afterwards.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "recording_kit.hpp"
#include "tv/record/recorder.hpp"
#include "tv/record/replay.hpp"
#include "tv/world.hpp"

namespace {

using tvtest::Script;

TEST(BackgroundWriter, WritesTheSameBytesAsTheGameThreadWould) {
  Script a, b;
  tv::Recorder background(tv::RecorderOptions{a.keyframeEvery});
  a.run(background);
  tv::RecorderOptions inline_;
  inline_.keyframeEvery = b.keyframeEvery;
  inline_.background = false;
  tv::Recorder onTheGameThread(inline_);
  b.run(onTheGameThread);
  ASSERT_TRUE(background.ok()) << background.error();
  EXPECT_EQ(background.bytes(), onTheGameThread.bytes());
  EXPECT_FALSE(tv::Replay::fromBytes(background.bytes()).validate());
}

// 2000 bodies of 4 x 4 on a grid, each moved 1 px right per frame by a continuous mover.
struct Crowd {
  tv::World world{16};
  tv::Mover mover{tv::MoverSpec{}};
  std::vector<tv::ItemId> bodies;
  explicit Crowd(int n = 2000) {
    for (int i = 0; i < n; ++i) bodies.push_back(world.add({(i % 50) * 8.0, (i / 50) * 8.0, 4, 4}));
  }
  void tick() {
    for (const tv::ItemId id : bodies) {
      const tv::Rect r = world.rect(id);
      (void)mover.move(world, id, {r.x + 1, r.y});
    }
  }
};

TEST(BackgroundWriter, AGameFasterThanItsWriterWaitsAtTheBoundInsteadOfFillingMemory) {
  // The recording goes into a pipe that nobody reads for the first 300 ms: the writer blocks
  // on it, and the game — 40 frames of 2000 moves, about 8 MB of captured calls — must wait at
  // the 2 MiB bound rather than keep it all in memory. Then the pipe is read; the recording
  // that comes out of it is whole.
  const std::string path = ::testing::TempDir() + "slow_writer.fifo";
  ::unlink(path.c_str());
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  std::vector<std::uint8_t> received;
  std::thread reader([&] {
    const int fd = ::open(path.c_str(), O_RDONLY);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    std::uint8_t buf[1 << 16];
    for (;;) {
      const ssize_t n = ::read(fd, buf, sizeof buf);
      if (n <= 0) break;
      received.insert(received.end(), buf, buf + n);
    }
    ::close(fd);
  });
  tv::RecorderOptions o;
  o.maxQueueBytes = 2u << 20;
  std::uint64_t stalls = 0;
  {
    tv::Recorder rec(path, o);  // opening a pipe for writing waits for its reader
    Crowd crowd;
    crowd.world.attach(rec);
    for (int f = 0; f < 40; ++f) {
      crowd.tick();
      rec.frame();
    }
    rec.close();
    stalls = rec.stalls();
    EXPECT_TRUE(rec.ok()) << rec.error();
  }
  reader.join();
  ::unlink(path.c_str());
  EXPECT_GT(stalls, 0u);
  const tv::Replay replay = tv::Replay::fromBytes(received);
  EXPECT_EQ(replay.frames(), 41u);
  EXPECT_EQ(replay.summary().moves, 80000u);
  EXPECT_TRUE(replay.warnings().empty());
}

// Everything written into a pipe at `path`, read only once someone says go(): a disk that
// stalls, so that the recorder's writer is still writing when the game dies. Its reader thread
// starts only when asked, after the fork: a child forked while another thread holds a lock (the
// sanitizer's allocator, while that thread starts up) inherits it held and hangs on its first
// allocation.
class SlowDisk {
 public:
  explicit SlowDisk(std::string path) : path_(std::move(path)) {
    ::unlink(path_.c_str());
    if (::mkfifo(path_.c_str(), 0600) != 0 || ::pipe(go_) != 0) {
      throw std::runtime_error("mkfifo " + path_);
    }
  }
  ~SlowDisk() {
    go();
    if (reader_.joinable()) reader_.join();
    ::close(go_[0]);
    ::close(go_[1]);
    ::unlink(path_.c_str());
  }
  // The reader opens the pipe (the writer's open waits for it) and waits for go().
  void startReading() {
    reader_ = std::thread([this] {
      const int fd = ::open(path_.c_str(), O_RDONLY);
      char c;
      (void)::read(go_[0], &c, 1);
      std::uint8_t buf[1 << 16];
      for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n <= 0) break;
        bytes_.insert(bytes_.end(), buf, buf + n);
      }
      ::close(fd);
    });
  }
  [[nodiscard]] const std::string& path() const { return path_; }
  // The disk starts reading (from any process that shares this object's pipe).
  void go() const { (void)!::write(go_[1], "g", 1); }
  // Waits until the writer is gone.
  const std::vector<std::uint8_t>& bytes() {
    go();
    reader_.join();
    return bytes_;
  }

 private:
  std::string path_;
  int go_[2] = {-1, -1};
  std::thread reader_;
  std::vector<std::uint8_t> bytes_;
};

// Runs `die` in a child process that records a crowd onto `disk`: 5 frames of 20000 moves
// handed over (several times what a pipe holds, so the writer is stuck on the disk), then
// `die`. With `flushOnCrash` the disk starts reading just before the child dies (the flush
// must wait for it); without, only once the child is dead. Returns the child's wait status;
// a child still alive after a minute is killed and reported, so a hang fails here, named.
int recordThenDie(SlowDisk& disk, bool flushOnCrash, const std::function<void()>& die) {
  const pid_t pid = fork();  // before any thread of this test starts
  if (pid == 0) {
    tv::RecorderOptions o;
    o.flushOnCrash = flushOnCrash;
    auto* rec = new tv::Recorder(disk.path(), o);  // never closed: the process dies with it open
    auto* crowd = new Crowd;
    crowd->world.attach(*rec);
    for (int f = 0; f < 5; ++f) {
      for (int t = 0; t < 10; ++t) crowd->tick();
      rec->frame();
    }
    if (flushOnCrash) disk.go();
    die();
    std::_Exit(99);  // not reached
  }
  disk.startReading();
  int status = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      ADD_FAILURE() << "the recording child still ran after 60 s: killed";
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return status;
}

// Frames a recording holds (frame 5, the one being played, is never in it); 0 for none.
std::uint64_t framesIn(const std::vector<std::uint8_t>& bytes) {
  try {
    return tv::Replay::fromBytes(bytes).frames();
  } catch (const tv::Error&) {
    return 0;
  }
}

void throwTheGamesBug() {
  throw std::runtime_error("the game's bug");
}
// An exception cannot leave it: std::terminate, as for any exception nothing catches.
void callNoexcept(void (*f)()) noexcept {
  f();
}

TEST(CrashFlush, AbortKeepsEveryFrameHandedOverAndStillAborts) {
  SlowDisk disk(::testing::TempDir() + "crash_abort.fifo");
  const int status = recordThenDie(disk, true, [] { std::abort(); });
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGABRT);
  EXPECT_EQ(framesIn(disk.bytes()), 5u);  // frames 0..4
}

TEST(CrashFlush, ASegmentationFaultKeepsEveryFrameHandedOver) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer owns SIGSEGV (the crash flush leaves a handler alone)";
#endif
  SlowDisk disk(::testing::TempDir() + "crash_segv.fifo");
  const int status = recordThenDie(disk, true, [] { std::raise(SIGSEGV); });
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGSEGV);
  EXPECT_EQ(framesIn(disk.bytes()), 5u);
}

TEST(CrashFlush, AnUncaughtExceptionKeepsEveryFrameHandedOver) {
  SlowDisk disk(::testing::TempDir() + "crash_throw.fifo");
  const int status = recordThenDie(disk, true, [] { callNoexcept(&throwTheGamesBug); });
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(framesIn(disk.bytes()), 5u);
}

TEST(CrashFlush, ExitWithTheRecorderOpenKeepsEveryFrameHandedOver) {
  SlowDisk disk(::testing::TempDir() + "crash_exit.fifo");
  const int status = recordThenDie(disk, true, [] { std::exit(3); });
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 3);
  const tv::Replay r = tv::Replay::fromBytes(disk.bytes());
  EXPECT_EQ(r.frames(), 5u);
  ASSERT_EQ(r.warnings().size(), 1u);  // no end mark: the game never closed it
  EXPECT_NE(r.warnings()[0].find("no end mark"), std::string::npos) << r.warnings()[0];
}

TEST(CrashFlush, NegativeControlWithoutTheFlushTheFramesStillBeingWrittenAreLost) {
  // The same abort without waiting for the writer, stuck on the slow disk when the process
  // dies: the frames it had not written yet die with it.
  SlowDisk disk(::testing::TempDir() + "crash_noflush.fifo");
  const int status = recordThenDie(disk, false, [] { std::abort(); });
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_LT(framesIn(disk.bytes()), 5u);
}

// What SIGHUP does now (the signal a sanitizer leaves alone): the default, or a handler.
void (*hangUpHandler())(int) {
  struct sigaction now {};
  sigaction(SIGHUP, nullptr, &now);
  return now.sa_handler;
}

void gamesOwnHandler(int) {}

TEST(CrashFlush, TheHandlersAreThereOnlyWhileAFileRecorderIsOpen) {
  // A handler that stayed after the recorder closed would point into a library that may be
  // unloaded by then (the Lua module, when its Lua state closes).
  ASSERT_EQ(hangUpHandler(), SIG_DFL);
  const std::terminate_handler before = std::get_terminate();
  const std::string a = ::testing::TempDir() + "watch_a.tvrec";
  const std::string b = ::testing::TempDir() + "watch_b.tvrec";
  {
    tv::Recorder first(a);
    EXPECT_NE(hangUpHandler(), SIG_DFL);
    EXPECT_NE(std::get_terminate(), before);
    {
      tv::Recorder second(b);
      EXPECT_NE(hangUpHandler(), SIG_DFL);
    }
    EXPECT_NE(hangUpHandler(), SIG_DFL) << "one recorder is still open";
    first.close();
    EXPECT_EQ(hangUpHandler(), SIG_DFL);
  }
  EXPECT_EQ(hangUpHandler(), SIG_DFL);
  EXPECT_EQ(std::get_terminate(), before);
  // A recorder without a file has nothing to flush: it installs nothing.
  tv::Recorder memory;
  EXPECT_EQ(hangUpHandler(), SIG_DFL);
}

TEST(CrashFlush, AHandlerTheGameSetsWhileRecordingIsItsOwnAfterwards) {
  ASSERT_EQ(hangUpHandler(), SIG_DFL);
  {
    tv::Recorder rec(::testing::TempDir() + "watch_own.tvrec");
    std::signal(SIGHUP, &gamesOwnHandler);
  }
  EXPECT_EQ(hangUpHandler(), &gamesOwnHandler);
  std::signal(SIGHUP, SIG_DFL);
}

}  // namespace
