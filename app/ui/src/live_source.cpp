// A game running now, as a Source: the receiver's frames replayed as they arrive.
#include "tv/ui/live_source.hpp"

#include <algorithm>
#include <fstream>
#include <limits>

#include "tv/app/user_message.hpp"
#include "tv/error.hpp"

namespace tv::ui {

namespace {

constexpr std::uint64_t kNoFrames = std::numeric_limits<std::uint64_t>::max();

}  // namespace

LiveSource::LiveSource(std::shared_ptr<LiveReceiver> receiver) : rx_(std::move(receiver)) {
  if (!rx_) fail("tv::ui::LiveSource", "needs a receiver");
  window_ = rx_->window(kNoFrames);
}

std::string LiveSource::name() const {
  if (window_.run == 0) return "live: listening on " + rx_->address();
  return "live: " + (window_.peer.empty() ? std::string("game") : window_.peer) +
         (window_.run > 1 ? ", run " + std::to_string(window_.run) : std::string());
}

std::vector<std::string> LiveSource::refresh(bool newest) {
  std::vector<std::string> news;
  for (const LiveEvent& e : rx_->poll()) {
    // Frames arrive many times a second: the timeline shows them, the news does not.
    if (e.kind == LiveEvent::Kind::frames) continue;
    news.push_back(e.text);
  }
  const LiveWindow w = rx_->window(kNoFrames);
  if (w.run != window_.run && replay_) {
    // A game that connects again starts a new run: what was shown belongs to the last one.
    replay_.reset();
    base_ = built_ = 0;
  }
  window_ = w;
  const auto since = std::chrono::steady_clock::now() - builtAt_;
  const bool due = std::chrono::duration<double>(since).count() >= kRebuildSeconds;
  const bool more = w.nextFrame > built_;
  if ((!replay_ && w.nextFrame > 0) || (newest && more && (due || ended()))) rebuild();
  return news;
}

void LiveSource::rebuild() {
  std::vector<std::uint8_t> bytes;
  LiveWindow w;
  try {
    w = rx_->window(kNoFrames);
    bytes = rx_->file();
  } catch (const Error&) {
    return;  // no keyframe kept yet: nothing to replay
  }
  const std::optional<std::uint64_t> shown =
      replay_ ? std::optional<std::uint64_t>(frame()) : std::nullopt;
  const auto call = replay_ ? replay_->call() : std::nullopt;
  std::unique_ptr<ReplaySource> next;
  try {
    next = ReplaySource::fromBytes(
        std::make_shared<const std::vector<std::uint8_t>>(std::move(bytes)), "live",
        SourceKind::live);
  } catch (const Error& e) {
    notes_.assign(1, "the stream could not be replayed: " + app::userMessage(e));
    return;
  }
  // The file starts at the oldest keyframe kept, renumbered from 0.
  base_ = w.firstKept;
  built_ = w.nextFrame;
  replayRun_ = w.run;
  builtAt_ = std::chrono::steady_clock::now();
  replay_ = std::move(next);
  notes_.clear();
  if (traced_ && replay_->world().has(*traced_)) replay_->trace(traced_);
  if (shown) {
    replay_->goTo(*shown > base_ ? *shown - base_ : 0);
    if (call) replay_->selectCall(call);
  } else {
    replay_->goTo(replay_->lastFrame());
  }
}

std::unique_ptr<Source> LiveSource::rerun(const MoverSpec& mover) const {
  if (!replay_) fail("tv::ui::LiveSource", "no frames yet: a what-if needs a game's frames");
  return replay_->whatIf(mover, replay_->recording().options().updatesAsMoves);
}

// -- time ----------------------------------------------------------------------------------------

std::uint64_t LiveSource::frame() const {
  return replay_ ? base_ + replay_->frame() : 0;
}

std::uint64_t LiveSource::firstFrame() const {
  return replay_ ? std::max(base_, window_.firstKept) : window_.firstKept;
}

std::uint64_t LiveSource::lastFrame() const {
  return window_.nextFrame > 0 ? window_.nextFrame - 1 : 0;
}

bool LiveSource::ended() const {
  return window_.run > 0 && (window_.closed || !window_.connected);
}

void LiveSource::goTo(std::uint64_t f) {
  // Past what the replay holds: bring it up to what has arrived first.
  if ((!replay_ || f > base_ + replay_->lastFrame()) && window_.nextFrame > built_) rebuild();
  if (!replay_) return;
  replay_->goTo(f > base_ ? f - base_ : 0);
}

// -- delegated to the replay ---------------------------------------------------------------------

std::span<const CallInfo> LiveSource::calls() const {
  return replay_ ? replay_->calls() : std::span<const CallInfo>();
}
std::optional<std::uint32_t> LiveSource::call() const {
  return replay_ ? replay_->call() : std::nullopt;
}
void LiveSource::selectCall(std::optional<std::uint32_t> k) {
  if (replay_) {
    replay_->selectCall(k);
    traced_ = replay_->traced();
  }
}
bool LiveSource::traces(const CallInfo& c) const {
  return replay_ && replay_->traces(c);
}
void LiveSource::trace(std::optional<ItemId> item) {
  traced_ = item;
  if (replay_) replay_->trace(item);
}
std::optional<ItemId> LiveSource::traced() const {
  return traced_;
}
std::span<const TracedMove> LiveSource::history() const {
  return replay_ ? replay_->history() : std::span<const TracedMove>();
}
const MoveTrace* LiveSource::callTrace() const {
  return replay_ ? replay_->callTrace() : nullptr;
}
const World& LiveSource::world() const {
  return replay_ ? replay_->world() : empty_;
}
WorldPicture LiveSource::picture() {
  if (replay_) return replay_->picture();
  WorldPicture p;
  p.world = &empty_;
  return p;
}
Rect LiveSource::home() const {
  return replay_ ? replay_->home() : Rect{0, 0, 320, 180};
}
double LiveSource::followMinSide() const {
  return replay_ ? replay_->followMinSide() : 64.0;
}
std::string LiveSource::describe(ItemId id) const {
  return replay_ ? replay_->describe(id) : "item " + std::to_string(id.index);
}
std::string LiveSource::category(ItemId id) const {
  return replay_ ? replay_->category(id) : std::string();
}
std::vector<ItemRow> LiveSource::items() const {
  std::vector<ItemRow> rows = replay_ ? replay_->items() : std::vector<ItemRow>{};
  for (ItemRow& r : rows) {
    r.firstFrame += base_;
    r.lastFrame += base_;
  }
  return rows;
}

std::vector<std::string> LiveSource::notes() const {
  std::vector<std::string> out = notes_;
  if (window_.run == 0) {
    out.push_back("waiting for a game at " + rx_->address() + ": run one with --live " +
                  rx_->address() + ", or with TV_LIVE=" + rx_->address() + " where it reads it (tv::liveFromEnvironment)");
  } else if (window_.dropped > 0) {
    out.push_back("dropped the oldest " + std::to_string(window_.dropped) +
                  " frames to stay within the receiver's bounds (frames " +
                  std::to_string(firstFrame()) + ".." + std::to_string(lastFrame()) + " kept)");
  }
  if (ended()) {
    out.push_back(std::string(window_.closed ? "the game closed its recording" : "the game left") +
                  ": a game that connects again starts a new run");
  }
  return out;
}

void LiveSource::save(const std::string& path) const {
  const std::vector<std::uint8_t> bytes = rx_->file();  // throws when nothing is kept
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) fail("tv::ui::LiveSource", "cannot write '" + path + "'");
}

}  // namespace tv::ui
