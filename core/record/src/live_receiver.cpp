// The receiver's side of a live stream (tv/record/live.hpp): a thread of its own accepts one
// game at a time, reads its stream through a StreamReader (every byte untrusted), keeps the
// newest frames within the bounds, and hands frames and events to a UI under one mutex.
//
// Index: [SECTION] state · [SECTION] the UI's side · [SECTION] the stream ·
//        [SECTION] the connection

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <mutex>
#include <thread>

#include "socket.hpp"
#include "stream_reader.hpp"
#include "tv/record/live.hpp"

namespace tv {

namespace {

constexpr std::size_t kMaxEvents = 1024;
constexpr std::size_t kFrameOverhead = 128;  // bookkeeping per kept frame, counted as bytes

std::string mib(std::uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f MiB", static_cast<double>(bytes) / (1 << 20));
  return text;
}

// "game.tvrec" for run 1, "game-2.tvrec" for run 2.
std::string runPath(const std::string& path, std::uint64_t run) {
  if (run <= 1) return path;
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  std::string suffix = "-";  // appended, not added: GCC 12's false -Wrestrict (bug 105329)
  suffix += std::to_string(run);
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return path + suffix;
  return path.substr(0, dot) + suffix + path.substr(dot);
}

}  // namespace

// [SECTION] state ---------------------------------------------------------------------------------

struct LiveReceiver::Impl final : rec::StreamReader::Sink {
  LiveReceiverOptions options;
  rec::net::Address address;
  rec::net::Fd listener;
  rec::net::Waker waker;
  std::atomic<bool> stopping{false};
  std::thread thread;

  // The connection: the thread's own.
  rec::net::Fd conn;
  std::unique_ptr<rec::StreamReader> reader;
  double lastByte = 0.0;
  std::FILE* save = nullptr;
  std::string savePath;
  bool hostile = false;
  bool stopNow = false;  // stopAfterFrames reached

  // Shared with the UI, under m.
  mutable std::mutex m;
  std::condition_variable arrived;
  std::deque<LiveEvent> events;
  std::uint64_t eventsLost = 0;
  std::uint64_t run = 0;
  bool connected = false, controllable = false, closed = false;
  std::string peer;
  std::array<std::uint8_t, 32> fileHeader{};
  std::deque<std::shared_ptr<const LiveFrame>> frames;
  std::uint64_t firstKept = 0, nextFrame = 0, dropped = 0, bytes = 0;
  bool keyframeAsked = false;
  std::vector<std::uint8_t> outbox;  // commands for the game
  bool dropWanted = false;           // the UI asked to disconnect

  void event(LiveEvent::Kind kind, std::string text, std::uint64_t frame = 0,
             std::uint64_t count = 0);  // under m
  void loop();
  void accept();
  void read();
  void sendCommands();
  void endRun(const std::string& why, bool byUs);
  void closeSave(bool endMark);
  void enforceBounds();  // under m
  [[nodiscard]] std::string droppedText(std::uint64_t n, std::uint64_t total) const;

  // StreamReader::Sink, on the thread.
  void hello(std::uint32_t flags) override;
  void header(const std::array<std::uint8_t, rec::kHeaderSize>& bytes,
              const rec::HeaderInfo& info) override;
  void frame(LiveFrame&& f) override;
  void end() override;
};

void LiveReceiver::Impl::event(LiveEvent::Kind kind, std::string text, std::uint64_t frame,
                               std::uint64_t count) {
  // Frames arriving, and frames dropped: one event of each says how many, until it is read.
  if (kind == LiveEvent::Kind::frames || kind == LiveEvent::Kind::dropped) {
    for (auto it = events.rbegin(); it != events.rend(); ++it) {
      if (it->run != run) break;
      if (it->kind != kind) continue;
      it->frame = frame;
      it->count += count;
      it->text =
          kind == LiveEvent::Kind::frames ? std::move(text) : droppedText(it->count, dropped);
      arrived.notify_all();
      return;
    }
  }
  {
    events.push_back({kind, run, frame, count, std::move(text)});
    if (events.size() > kMaxEvents) {
      events.pop_front();
      ++eventsLost;
    }
  }
  arrived.notify_all();
}

// [SECTION] the UI's side ------------------------------------------------------------------------

LiveReceiver::LiveReceiver(LiveReceiverOptions options) : impl_(std::make_unique<Impl>()) {
  Impl& d = *impl_;
  if (options.keepBytes < (std::uint64_t{1} << 20)) {
    fail("tv::LiveReceiverOptions",
         "keepBytes must be at least 1 MiB, but was " + std::to_string(options.keepBytes));
  }
  if (options.maxChunk < 64 || options.maxChunk > rec::kMaxChunk) {
    fail("tv::LiveReceiverOptions",
         "maxChunk must be in [64, 2^30], but was " + std::to_string(options.maxChunk));
  }
  if (!(options.stallSeconds > 0 && options.stallSeconds <= 3600)) {
    fail("tv::LiveReceiverOptions",
         "stallSeconds must be in (0, 3600], but was " + formatNumber(options.stallSeconds));
  }
  d.options = std::move(options);
  d.address = rec::net::parseAddress(d.options.address, "tv::LiveReceiverOptions::address", true);
  d.listener = rec::net::listenOn(d.address);  // throws: in use, not listenable
  d.address.port = rec::net::localPort(d.listener.get());
  d.thread = std::thread([&d] { d.loop(); });
}

LiveReceiver::~LiveReceiver() {
  Impl& d = *impl_;
  d.stopping.store(true, std::memory_order_release);
  d.waker.wake();
  if (d.thread.joinable()) d.thread.join();
}

std::uint16_t LiveReceiver::port() const {
  return impl_->address.port;
}

std::string LiveReceiver::address() const {
  return impl_->address.text();
}

std::vector<LiveEvent> LiveReceiver::poll() {
  Impl& d = *impl_;
  std::lock_guard lock(d.m);
  std::vector<LiveEvent> out;
  if (d.eventsLost > 0) {
    out.push_back({LiveEvent::Kind::refused, d.run, 0, d.eventsLost,
                   std::to_string(d.eventsLost) + " older events were not read in time"});
    d.eventsLost = 0;
  }
  out.insert(out.end(), std::make_move_iterator(d.events.begin()),
             std::make_move_iterator(d.events.end()));
  d.events.clear();
  return out;
}

bool LiveReceiver::wait(double seconds) {
  Impl& d = *impl_;
  std::unique_lock lock(d.m);
  return d.arrived.wait_for(lock, std::chrono::duration<double>(std::max(0.0, seconds)),
                            [&] { return !d.events.empty() || d.eventsLost > 0; });
}

LiveWindow LiveReceiver::window(std::uint64_t from) const {
  const Impl& d = *impl_;
  std::lock_guard lock(d.m);
  LiveWindow w;
  w.run = d.run;
  w.connected = d.connected;
  w.controllable = d.controllable;
  w.closed = d.closed;
  w.peer = d.peer;
  w.header = d.fileHeader;
  w.firstKept = d.firstKept;
  w.nextFrame = d.nextFrame;
  w.dropped = d.dropped;
  w.bytes = d.bytes;
  const std::uint64_t start = std::max(from, d.firstKept);
  if (start < d.nextFrame) {
    w.frames.assign(d.frames.begin() + static_cast<std::ptrdiff_t>(start - d.firstKept),
                    d.frames.end());
  }
  return w;
}

std::vector<std::uint8_t> LiveReceiver::file() const {
  const Impl& d = *impl_;
  std::lock_guard lock(d.m);
  if (d.run == 0) fail("tv::LiveReceiver::file", "no game has connected yet");
  const auto key =
      std::find_if(d.frames.begin(), d.frames.end(), [](const auto& f) { return f->keyframe; });
  if (key == d.frames.end()) {
    fail("tv::LiveReceiver::file", "no keyframe is kept yet (the game was asked for one)");
  }
  std::vector<std::uint8_t> out(d.fileHeader.begin(), d.fileHeader.end());
  const std::uint64_t base = (*key)->number;
  for (auto it = key; it != d.frames.end(); ++it) {
    const LiveFrame& f = **it;
    const std::span<const std::uint8_t> payload(f.chunk.data() + 8, f.chunk.size() - 8);
    const std::vector<std::uint8_t> c =
        base == 0 ? f.chunk
                  : rec::renumberChunk(payload, f.number - base,
                                       it == key ? std::span<const std::uint8_t>(f.labels)
                                                 : std::span<const std::uint8_t>(),
                                       f.keyframeEnd);
    out.insert(out.end(), c.begin(), c.end());
  }
  if (d.closed) {
    for (int i = 0; i < 4; ++i) out.push_back(0);
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(rec::kEndMark >> (8 * i)));
  }
  return out;
}

namespace {
bool command(LiveReceiver::Impl& d, std::uint8_t byte, const char* asked) {
  std::lock_guard lock(d.m);
  if (!d.connected) {
    d.event(LiveEvent::Kind::control, std::string("cannot ") + asked + ": no game is connected");
    return false;
  }
  if (!d.controllable && byte != rec::kCommandResume) {
    d.event(LiveEvent::Kind::control,
            std::string("cannot ") + asked +
                ": the game does not accept pause and step (its LiveOptions::control is off)");
    return false;
  }
  d.outbox.push_back(byte);
  d.event(LiveEvent::Kind::control, std::string("asked the game to ") + asked);
  d.waker.wake();
  return true;
}
}  // namespace

bool LiveReceiver::pause() {
  return command(*impl_, rec::kCommandPause, "pause");
}
bool LiveReceiver::step() {
  return command(*impl_, rec::kCommandStep, "step one frame");
}
bool LiveReceiver::resume() {
  return command(*impl_, rec::kCommandResume, "resume");
}

void LiveReceiver::disconnect() {
  Impl& d = *impl_;
  std::lock_guard lock(d.m);
  d.dropWanted = true;
  d.waker.wake();
}

// [SECTION] the stream ----------------------------------------------------------------------------

void LiveReceiver::Impl::hello(std::uint32_t flags) {
  std::lock_guard lock(m);
  controllable = (flags & rec::kHelloControl) != 0;
  event(LiveEvent::Kind::connected, "game " + peer + " connected: run " + std::to_string(run) +
                                        " (pause and step: " + (controllable ? "yes" : "no") + ")");
}

void LiveReceiver::Impl::header(const std::array<std::uint8_t, rec::kHeaderSize>& h,
                                const rec::HeaderInfo&) {
  {
    std::lock_guard lock(m);
    std::copy(h.begin(), h.end(), fileHeader.begin());
  }
  if (options.saveTo.empty()) return;
  savePath = runPath(options.saveTo, run);
  save = std::fopen(savePath.c_str(), "wb");
  if (!save || std::fwrite(h.data(), 1, h.size(), save) != h.size()) {
    std::lock_guard lock(m);
    event(LiveEvent::Kind::refused, "cannot write '" + savePath + "': the run is not saved");
    if (save) std::fclose(save);
    save = nullptr;
  }
}

void LiveReceiver::Impl::frame(LiveFrame&& f) {
  if (stopNow) return;  // past stopAfterFrames: the run ends at the last one wanted
  f.run = run;
  if (save) {
    if (std::fwrite(f.chunk.data(), 1, f.chunk.size(), save) != f.chunk.size() ||
        std::fflush(save) != 0) {
      std::fclose(save);
      save = nullptr;
      std::lock_guard lock(m);
      event(LiveEvent::Kind::refused, "writing '" + savePath + "' failed: the run is not saved");
    }
  }
  auto shared = std::make_shared<const LiveFrame>(std::move(f));
  std::lock_guard lock(m);
  if (shared->keyframe) keyframeAsked = false;
  bytes += shared->chunk.size() + shared->labels.size() + kFrameOverhead;
  const std::uint64_t number = shared->number;
  frames.push_back(std::move(shared));
  nextFrame = number + 1;
  enforceBounds();
  event(LiveEvent::Kind::frames, "frames up to " + std::to_string(number), number, 1);
  if (options.stopAfterFrames > 0 && number + 1 >= options.stopAfterFrames) stopNow = true;
}

void LiveReceiver::Impl::enforceBounds() {
  const auto over = [&] {
    return (options.keepFrames > 0 && frames.size() > options.keepFrames) ||
           bytes > options.keepBytes;
  };
  std::uint64_t gone = 0;
  while (frames.size() > 1 && over()) {
    // A keyframe's group at a time, so that what is kept starts at a keyframe.
    std::size_t n = 1;
    while (n < frames.size() && !frames[n]->keyframe) ++n;
    if (n == frames.size()) {
      n = 1;  // no later keyframe: the oldest frame alone, and the game is asked for one
      if (!keyframeAsked) {
        outbox.push_back(rec::kCommandKeyframe);
        keyframeAsked = true;
        waker.wake();
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      bytes -= frames.front()->chunk.size() + frames.front()->labels.size() + kFrameOverhead;
      frames.pop_front();
    }
    gone += n;
  }
  if (gone == 0) return;
  dropped += gone;
  firstKept = frames.front()->number;
  event(LiveEvent::Kind::dropped, droppedText(gone, dropped), firstKept, gone);
}

std::string LiveReceiver::Impl::droppedText(std::uint64_t n, std::uint64_t total) const {
  return "dropped the oldest " + std::to_string(n) + " frames to keep within " +
         (options.keepFrames ? std::to_string(options.keepFrames) + " frames and " : "") +
         mib(options.keepBytes) + " (" + std::to_string(total) + " dropped in this run)";
}

void LiveReceiver::Impl::end() {
  {
    std::lock_guard lock(m);
    closed = true;
  }
  closeSave(true);
}

void LiveReceiver::Impl::closeSave(bool endMark) {
  if (!save) return;
  if (endMark) {
    std::uint8_t mark[8] = {0, 0, 0, 0};
    for (int i = 0; i < 4; ++i) mark[4 + i] = static_cast<std::uint8_t>(rec::kEndMark >> (8 * i));
    std::fwrite(mark, 1, 8, save);
  }
  std::fclose(save);
  save = nullptr;
}

// [SECTION] the connection ------------------------------------------------------------------------

void LiveReceiver::Impl::loop() {
  while (!stopping.load(std::memory_order_acquire)) {
    rec::net::Watch fds[3] = {{waker.fd(), rec::net::kIn},
                              {listener.get(), rec::net::kIn},
                              {rec::net::kNoSocket, rec::net::kIn}};
    int timeout = -1;
    if (conn) {
      fds[2].fd = conn.get();
      // A peer in the middle of something — its hello, a header, a chunk — must go on.
      if (!reader->ended() && (reader->midItem() || reader->frames() == 0)) {
        timeout = std::max(
            0, static_cast<int>((lastByte + options.stallSeconds - rec::net::now()) * 1000) + 1);
      }
      std::lock_guard lock(m);
      if (!outbox.empty()) fds[2].events |= rec::net::kOut;
    }
    rec::net::wait(fds, 3, timeout);
    if (fds[0].revents) waker.drain();
    if (stopping.load(std::memory_order_acquire)) break;
    bool drop;
    {
      std::lock_guard lock(m);
      drop = dropWanted;
      dropWanted = false;
    }
    if (conn && drop) endRun("stopped receiving (asked)", true);
    if (fds[1].revents) accept();
    if (conn && (fds[2].revents & (rec::net::kIn | rec::net::kHangUp | rec::net::kError))) read();
    if (conn) sendCommands();
    if (conn && !reader->ended() && (reader->midItem() || reader->frames() == 0) &&
        rec::net::now() - lastByte > options.stallSeconds) {
      hostile = true;
      endRun("dropped it: nothing for " + formatNumber(options.stallSeconds) +
                 " s in the middle of " + reader->awaiting(),
             false);
    }
  }
  if (conn) endRun("the receiver stopped", true);
}

void LiveReceiver::Impl::accept() {
  for (;;) {
    rec::net::Fd c = rec::net::acceptNext(listener.get());
    if (!c) return;
    const std::string who = rec::net::peerName(c.get());
    if (conn) {
      std::lock_guard lock(m);
      event(LiveEvent::Kind::refused,
            "refused a second game from " + who + ": receiving from " + peer + " already");
      continue;  // closed as it goes
    }
    std::string why;
    if (rec::net::sendSome(c.get(), rec::kLiveReply, sizeof rec::kLiveReply, why) !=
        static_cast<long>(sizeof rec::kLiveReply)) {
      continue;  // gone already
    }
    conn = std::move(c);
    reader = std::make_unique<rec::StreamReader>(
        rec::StreamReader::Limits{options.maxChunk, options.maxCells});
    lastByte = rec::net::now();
    hostile = false;
    stopNow = false;
    std::lock_guard lock(m);
    ++run;
    connected = true;
    controllable = false;
    closed = false;
    peer = who;
    fileHeader = {};
    frames.clear();
    firstKept = nextFrame = dropped = bytes = 0;
    keyframeAsked = false;
    outbox.clear();
  }
}

void LiveReceiver::Impl::read() {
  static constexpr std::size_t kBuf = 1 << 16;
  std::uint8_t buf[kBuf];
  // A flooding peer gets its turn, then the UI's commands and the listener get theirs.
  for (int turn = 0; turn < 64 && conn; ++turn) {
    std::string why;
    const long n = rec::net::recvSome(conn.get(), buf, kBuf, why);
    if (n == 0) return;
    if (n < 0) {
      endRun(why == "closed" ? (reader->ended() ? "the game closed its recording"
                                                : "the game disconnected without closing its "
                                                  "recording")
                             : "the connection failed: " + why,
             false);
      return;
    }
    lastByte = rec::net::now();
    try {
      reader->feed(buf, static_cast<std::size_t>(n), *this);
    } catch (const std::exception& e) {  // tv::Error for hostile bytes; bad_alloc alike
      hostile = true;
      endRun(std::string("refused the stream: ") + e.what(), false);
      return;
    }
    if (stopNow) {
      endRun("stopped after " + std::to_string(options.stopAfterFrames) + " frames, as asked",
             true);
      return;
    }
  }
}

void LiveReceiver::Impl::sendCommands() {
  std::lock_guard lock(m);
  if (outbox.empty()) return;
  std::string why;
  const long n = rec::net::sendSome(conn.get(), outbox.data(), outbox.size(), why);
  if (n > 0) outbox.erase(outbox.begin(), outbox.begin() + n);
}

void LiveReceiver::Impl::endRun(const std::string& why, bool byUs) {
  // A run ended on purpose (disconnect(), a receiver that stops) ends its saved file as a
  // recording that was closed: every whole frame, then the end mark.
  closeSave(byUs && reader && !reader->ended() && reader->frames() > 0);
  conn.reset();
  std::lock_guard lock(m);
  const std::uint64_t n = reader ? reader->frames() : 0;
  connected = false;
  if (byUs && n > 0) closed = true;
  outbox.clear();
  event(hostile ? LiveEvent::Kind::refused : LiveEvent::Kind::ended,
        "game " + peer + ", run " + std::to_string(run) + ": " + why + " (" + std::to_string(n) +
            " frames)",
        n, n);
  hostile = false;
}

}  // namespace tv
