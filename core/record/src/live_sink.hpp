#pragma once
// The game's side of a live stream (tv/record/live.hpp): a thread of its own connects to the
// receiver, sends the hello and then the recorder's chunks, and reads the receiver's commands.
// The recorder's writer hands it chunks (LiveOut, on the writer's thread); the game's thread
// asks it whether to capture, whether to make a keyframe, and waits in it while paused.
//
// A run starts at a keyframe: the connection asks the game's thread for one at its next frame
// mark, and the run's first chunk is that frame's, renumbered 0, with the labels of the items
// then in the world put after its keyframe; each later chunk is renumbered from there.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <unordered_map>
#include <utility>
#include <vector>

#include "live_out.hpp"
#include "socket.hpp"
#include "tv/record/live.hpp"

namespace tv::rec {

class LiveSink final : public LiveOut {
 public:
  // Throws tv::Error when the address or the options are malformed.
  explicit LiveSink(LiveOptions options);
  ~LiveSink() override;
  LiveSink(const LiveSink&) = delete;
  LiveSink& operator=(const LiveSink&) = delete;

  // Sends what is queued (at most 1 s more), closes the connection, ends the thread.
  void stop();

  // -- the game's thread ---------------------------------------------------------------------
  // A receiver is there (a live-only recorder copies calls only then).
  [[nodiscard]] bool connected() const { return connected_.load(std::memory_order_acquire); }
  // The next frame should be a keyframe (a receiver joined, or asked for one): true once.
  bool takeKeyframeRequest() { return keyframeWanted_.exchange(false, std::memory_order_acq_rel); }
  // At a frame mark: blocks while the receiver holds the game (control on), lets a step pass.
  void waitWhilePaused();
  [[nodiscard]] LiveStatus status() const;

  // -- the writer's thread (LiveOut) ---------------------------------------------------------
  void header(const std::array<std::uint8_t, kHeaderSize>& header) override;
  void keyframe(std::uint64_t frame, std::size_t callsAt, bool mayStart) override;
  void chunk(std::uint64_t frame, const std::uint8_t (&head)[8],
             std::span<const std::uint8_t> payload, const Model& model) override;
  void end(const std::uint8_t (&endMark)[8]) override;
  void label(ItemId id, std::string_view label, std::string_view category) override;
  void removed(ItemId id) override;

 private:
  void run();
  void tryConnect();
  void connectedNow();
  void readCommands();
  bool sendQueued();  // false: the connection failed
  void disconnect(const std::string& why);
  void say(const std::string& message);
  void enqueue(std::vector<std::uint8_t> bytes);  // under m_

  LiveOptions options_;
  net::Address address_;
  std::string addressText_;

  // The connection, owned by the thread.
  net::Waker waker_;
  net::Fd sock_;
  bool connecting_ = false;
  double deadline_ = 0.0;  // of the connect, or of the receiver's reply
  bool replied_ = false;
  std::size_t replyBytes_ = 0;
  double nextTry_ = 0.0;
  std::string lastFailure_;  // said once, until it changes
  std::size_t sentOfFront_ = 0;

  // Shared, under m_.
  mutable std::mutex m_;
  std::condition_variable resumed_;  // the game waits on it while paused
  std::atomic<bool> connected_{false};
  std::atomic<bool> keyframeWanted_{false};
  std::atomic<bool> stopping_{false};
  std::uint64_t epoch_ = 0;  // connections made
  bool awaitingKeyframe_ = false;
  std::optional<std::uint64_t> base_;  // the recorder's number of the run's frame 0
  std::deque<std::vector<std::uint8_t>> queue_;
  std::size_t pending_ = 0;
  bool overflow_ = false;
  bool paused_ = false;
  std::uint32_t steps_ = 0;
  LiveStatus status_;

  // The writer's thread only.
  std::array<std::uint8_t, kHeaderSize> header_{};
  std::optional<std::uint64_t> startFrame_;  // a keyframe frame that will begin the run
  std::size_t startCallsAt_ = 0;
  std::vector<std::uint8_t> startLabels_;
  std::unordered_map<ItemId, std::pair<std::string, std::string>> labels_;

  std::thread thread_;
};

}  // namespace tv::rec
