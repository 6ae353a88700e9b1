#pragma once
/// A game watched while it runs: the recorder's own chunks streamed over a TCP socket (loopback
/// unless the user names another host) to a receiver — tv-debugger, `tv-replay --listen`, or
/// any program using tv::LiveReceiver. A stream saved is a valid `.tvrec` file
/// (core/record/FORMAT.md, "Live streams"). POSIX sockets, or Winsock 2 on Windows (a program
/// linking tv::record statically there also links ws2_32; the CMake package names it).
///
/// The game's side (Recorder::stream, or a Recorder made from LiveOptions alone):
///
///   tv::LiveOptions live;
///   live.address = "127.0.0.1:7720";       // where the debugger listens
///   live.control = true;                   // the debugger may pause and step the game
///   tv::Recorder rec(live);                // streams only; or rec.stream(live) on a file recorder
///   world.attach(rec);
///   rec.attach(fixedStep);                 // frame marks: where a pause holds the game
///
/// The game connects to the receiver, never the other way round, and never waits for it: the
/// connection is tried on a thread of the recorder's own, every `retrySeconds` while nobody
/// listens (one message says so, then it is quiet), and a live-only recorder copies nothing
/// until a receiver is there. A receiver that joins mid-game gets a keyframe at the game's next
/// frame mark, with the labels of the items then in the world; a game that reconnects starts a
/// new run. A receiver that falls `maxPendingBytes` behind is dropped rather than slow the game.
///
/// The receiver's side — a UI reads frames as they arrive, from any thread:
///
///   tv::LiveReceiver rx({.address = "7720", .keepBytes = 256 << 20});
///   for (;;) {                                   // a UI's frame
///     for (const tv::LiveEvent& e : rx.poll()) show(e.text);
///     tv::LiveWindow w = rx.window(next);        // frames `next` onwards (shared, not copied)
///     for (const auto& f : w.frames) append(*f);
///     next = w.nextFrame;
///     if (w.dropped > shownDropped) say("dropped the oldest ...");
///   }
///   rx.pause(); rx.step(); rx.resume();          // a game that allows it stops at its next mark
///   tv::Replay r = tv::Replay::fromBytes(rx.file());  // the frames kept, as a recording
///
/// Every byte a receiver reads is untrusted, as a file's: a malformed, truncated, tampered,
/// silent-mid-chunk or flooding peer gets a clear message (an event) and a closed connection,
/// never a crash, a hang or memory beyond `keepBytes` plus one chunk (`maxChunk`).

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tv/error.hpp"  // what they throw

namespace tv {

/// The game's side of a live stream. Recorder(LiveOptions) and Recorder::stream throw
/// tv::Error naming the field and its value when one is malformed or out of range.
struct LiveOptions {
  /// Where the receiver listens: "HOST:PORT", "[IPv6]:PORT", or "PORT" (host 127.0.0.1); port
  /// 1..65535. Default "127.0.0.1:7720".
  std::string address = "127.0.0.1:7720";
  /// Let the receiver pause the game and step it a frame at a time: the game's frame mark
  /// (Recorder::frame, or its FixedStep's advance) then blocks while it is paused. Off: pause
  /// requests are refused and the game never waits.
  bool control = false;
  /// Seconds between connection attempts while no receiver listens. Range [0.05, 3600];
  /// default 2.
  double retrySeconds = 2.0;
  /// Most bytes of frames waiting to be sent (at least 1 MiB; default 64 MiB): a receiver
  /// further behind is disconnected, and the game goes on.
  std::size_t maxPendingBytes = std::size_t{64} << 20;
  /// Told each change of the connection ("connected to 127.0.0.1:7720", "no receiver at
  /// 127.0.0.1:7720 (connection refused); trying again every 2 s", "disconnected: ..."), on
  /// the stream's own thread. Default: one line on stderr, "tv live: ...".
  std::function<void(std::string_view)> onMessage;
};

/// The live stream a `TV_LIVE=HOST:PORT` (or `name`) environment variable asks for; nullopt
/// when it is unset or empty. Throws tv::Error naming the variable and its value when it is
/// not an address. (For bindings: the Lua module attaches `Recorder(LiveOptions)` with it.)
[[nodiscard]] std::optional<LiveOptions> liveFromEnvironment(const char* name = "TV_LIVE");

/// Where the connection of a live stream stands (Recorder::liveStatus).
struct LiveStatus {
  bool connected = false;        ///< a receiver is there
  bool paused = false;           ///< the receiver holds the game at its frame marks
  std::uint64_t runs = 0;        ///< connections made so far
  std::uint64_t framesSent = 0;  ///< in the current run
  std::string peer;              ///< the receiver's address, when connected
  std::string message;           ///< the last message (what onMessage was told)
};

/// The receiver's side.
struct LiveReceiverOptions {
  /// Where to listen: "HOST:PORT", "[IPv6]:PORT" or "PORT" (127.0.0.1: loopback unless the
  /// user asks for another address). Port 0 takes any free port (see LiveReceiver::port).
  std::string address = "127.0.0.1:7720";
  /// Most frames kept of the current run (0, the default: no limit by count). Beyond it the
  /// oldest are dropped, a keyframe's group at a time so that what is kept can be replayed.
  std::uint64_t keepFrames = 0;
  /// Most bytes of frames kept of the current run (chunks as a file holds them, plus each
  /// keyframe's labels); beyond it the oldest are dropped as for keepFrames. At least 1 MiB
  /// (the constructor throws tv::Error below that); default 256 MiB. A receiver's memory is
  /// bounded by this plus one chunk being read (maxChunk).
  std::uint64_t keepBytes = std::uint64_t{256} << 20;
  /// Bytes: a chunk longer than this is refused as hostile and its game disconnected. Range
  /// [64, 2^30] (the constructor throws tv::Error outside it); default 64 MiB.
  std::uint32_t maxChunk = std::uint32_t{64} << 20;
  /// A peer that has begun its hello, its header or a chunk and then sends nothing for this
  /// many seconds is dropped (range (0, 3600], default 10; the constructor throws tv::Error
  /// outside it). A game between frames — paused, or in a menu — may be silent as long as it
  /// likes.
  double stallSeconds = 10.0;
  /// The cell budget of the world the stream describes (ReplayOptions::maxCells): a call that
  /// would visit more cells of the spatial hash is refused as hostile. Default 2^22.
  std::uint64_t maxCells = std::uint64_t{1} << 22;
  /// Also write each run whole, as it arrives, to this file (flushed per frame): run 1 to it,
  /// run n > 1 to the same name with "-n" before the extension. Empty (the default): none. A
  /// file that cannot be written is a `refused` event naming it and the run is not saved; the
  /// receiving goes on.
  std::string saveTo;
  /// End each run after this many frames (0, the default: never): the receiver disconnects the
  /// game then, and its saved file ends there as a closed recording.
  std::uint64_t stopAfterFrames = 0;
};

/// One whole frame as it arrived, checked (checksum, structure, every call decoded).
struct LiveFrame {
  std::uint64_t run = 0;     ///< the run it belongs to: 1 for the first game that connected
  std::uint64_t number = 0;  ///< its number in the run: 0 is the first frame received
  /// It opens with a whole-world snapshot (the first frame of a run always does), so that a
  /// recording can begin here.
  bool keyframe = false;
  std::uint32_t calls = 0;  ///< the calls it holds, labels included (not the snapshot)
  /// Moves among them: World::move and Mover::move calls, and each body of a Batch::step.
  std::uint64_t moves = 0;
  /// The chunk as a file holds it: 8-byte head (length, CRC-32) and payload.
  std::vector<std::uint8_t> chunk;
  /// For a keyframe: label calls of the items then in the world, which a recording that
  /// begins here repeats (LiveReceiver::file); empty for other frames.
  std::vector<std::uint8_t> labels;
  /// For a keyframe: the offset in the payload (bytes after the 8-byte head) where the
  /// snapshot ends and its calls begin; 0 for other frames.
  std::uint32_t keyframeEnd = 0;
};

/// Something that happened to a receiver, for its user (LiveReceiver::poll).
struct LiveEvent {
  /// What happened.
  enum class Kind : std::uint8_t {
    connected,  ///< a game connected: a new run
    frames,     ///< frames arrived (`frame`: the newest, `count`: how many since the last poll)
    dropped,    ///< the oldest were dropped to stay within the bounds (`count` since the last
                ///< poll; `frame`: the oldest kept now)
    ended,      ///< the run ended: the game closed its recording, or disconnected
    refused,    ///< a peer was refused: hostile bytes, a stall, a second game, ...
    control,    ///< a pause, step or resume was sent or could not be
  };
  Kind kind = Kind::frames;  ///< what happened
  std::uint64_t run = 0;     ///< the run it concerns (1 for the first game; 0 before any)
  std::uint64_t frame = 0;   ///< a frame number in that run, where `kind` says which
  std::uint64_t count = 0;   ///< frames, where `kind` says what they count
  std::string text;  ///< for people: "game 127.0.0.1:53122 connected (pause and step: yes)"
};

/// What is kept of the current run (or the last one), from a frame on.
struct LiveWindow {
  std::uint64_t run = 0;  ///< 0: no game has connected yet
  bool connected = false;     ///< the run's game is connected still
  bool controllable = false;  ///< the game accepts pause and step
  bool closed = false;        ///< the game ended its recording (the end mark came)
  std::string peer;           ///< the game's address, "127.0.0.1:53122"; empty before any run
  std::array<std::uint8_t, 32> header{};  ///< the run's file header
  std::uint64_t firstKept = 0;            ///< number of the oldest frame kept
  std::uint64_t nextFrame = 0;            ///< number the next frame will have
  std::uint64_t dropped = 0;              ///< frames of this run dropped so far
  std::uint64_t bytes = 0;                ///< kept
  /// Frames from max(from, firstKept) to nextFrame - 1, shared with the receiver (immutable).
  std::vector<std::shared_ptr<const LiveFrame>> frames;
};

/// Listens for one game's live stream at a time, on a thread of its own, and keeps the newest
/// frames of it within bounds (see the file's overview).
class LiveReceiver {
 public:
  /// Listens at options.address. Throws tv::Error when the address is malformed or taken
  /// ("127.0.0.1:7720 is in use by another program ...") or the bounds are out of range.
  explicit LiveReceiver(LiveReceiverOptions options = {});
  /// Closes the connection and stops listening.
  ~LiveReceiver();
  LiveReceiver(const LiveReceiver&) = delete;
  LiveReceiver& operator=(const LiveReceiver&) = delete;

  /// The port it listens on: the one asked for, or the one the system gave for port 0.
  [[nodiscard]] std::uint16_t port() const;
  [[nodiscard]] std::string address() const;  ///< "127.0.0.1:7720", with the port given

  // -- for a UI: thread-safe, and none waits for the network ----------------------------------
  /// The events since the last poll, oldest first (at most 1024 are kept between two polls;
  /// beyond that the oldest go, and a `refused`-kind note says how many).
  [[nodiscard]] std::vector<LiveEvent> poll();
  /// Waits until an event is pending or `seconds` pass; true when one is.
  bool wait(double seconds);
  /// The kept frames of the current (or last) run numbered `from` on.
  [[nodiscard]] LiveWindow window(std::uint64_t from = 0) const;
  /// The kept frames as a recording: the header, the frames from the oldest kept keyframe on
  /// (renumbered from 0, that keyframe's labels after it), the end mark if the game closed its
  /// recording. Throws tv::Error when no game has connected or no keyframe is kept.
  [[nodiscard]] std::vector<std::uint8_t> file() const;
  /// Back channel: the game stops at its next frame mark and waits there. Returns false (and
  /// a `control` event saying why) when no game is connected or the connected one does not
  /// accept control (LiveOptions::control); true once the request is queued to be sent.
  bool pause();
  /// Lets a paused game play one more frame, then it stops again at its next frame mark.
  /// Returns false, with a `control` event, as pause() does.
  bool step();
  /// Lets a paused game go on. Returns false, with a `control` event, as pause() does.
  bool resume();
  /// Drops the connected game (it will reconnect as a new run, if it still wants to).
  void disconnect();

  struct Impl;  ///< its state and thread (core/record/src/live_receiver.cpp)

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace tv
