// A recording as a Source: the replay, the frame and call on screen, the traced item's moves.
#include "tv/ui/replay_source.hpp"

#include <filesystem>

#include <algorithm>
#include <limits>

#include "tv/ui/palette.hpp"
#include "tv/ui/words.hpp"

namespace tv::ui {

std::unique_ptr<ReplaySource> ReplaySource::open(const std::string& path, ReplayOptions options) {
  // The debugger opens what can be opened; the bad chunk's error is a warning of the replay.
  options.tolerant = true;
  std::string name = std::filesystem::path(path).filename().string();
  if (options.mover) name += " with " + options.mover->name();
  return std::make_unique<ReplaySource>(Replay::open(path, options), name, Origin{path, nullptr});
}

std::unique_ptr<ReplaySource> ReplaySource::fromBytes(
    std::shared_ptr<const std::vector<std::uint8_t>> bytes, std::string name, SourceKind kind,
    ReplayOptions options) {
  options.tolerant = true;
  return std::make_unique<ReplaySource>(Replay::fromBytes(*bytes, options), std::move(name),
                                        Origin{{}, bytes}, kind);
}

ReplaySource::ReplaySource(Replay replay, std::string name, Origin origin, SourceKind kind)
    : replay_(std::move(replay)), name_(std::move(name)), origin_(std::move(origin)), kind_(kind) {
  const auto items = replay_.items();
  for (std::size_t i = 0; i < items.size(); ++i) recorded_.emplace(items[i].id, i);
  // The level's geometry: the category that more than half of the items that never move have
  // (blocks, tiles). Drawn as solids, with the items that have no category.
  std::unordered_map<std::string, std::size_t> still;
  std::size_t stillCount = 0;
  for (const RecordedItem& i : items) {
    hasNudges_ = hasNudges_ || i.nudges > 0;
    if (i.moves > 0 || i.updates > 0) continue;
    ++stillCount;
    if (!i.category.empty()) ++still[i.category];
  }
  for (const auto& [category, n] : still) {
    if (2 * n > stillCount) terrain_ = category;
  }
  goTo(0);
}

std::uint64_t ReplaySource::lastFrame() const {
  const std::uint64_t n = replay_.frames();
  return n > 0 ? n - 1 : 0;
}

void ReplaySource::goTo(std::uint64_t f) {
  f = std::min(f, lastFrame());
  // Playing forward: the replay already stands at the end of the frame on screen, so the next
  // frame is only its own calls, not a seek and the history again (a crowd's frames are big).
  const bool next = primed_ && !call_ && f == frame_ + 1;
  frame_ = f;
  call_.reset();
  calls_ = replay_.frames() > 0 ? replay_.calls(frame_) : std::vector<CallInfo>{};
  if (!next) return rebuild();
  divergence_.reset();
  callTraced_ = false;
  contactEvents_.clear();
  stepFrame(frame_, calls_, calls_.size());
  trimHistory();
}

void ReplaySource::selectCall(std::optional<std::uint32_t> k) {
  if (k && *k >= calls_.size()) return;
  call_ = k;
  // The call's item becomes the traced one, so its earlier moves trail behind the call's.
  if (k && calls_[*k].item.valid()) selected_ = calls_[*k].item;
  rebuild();
}

void ReplaySource::trace(std::optional<ItemId> item) {
  selected_ = item;
  rebuild();
}

void ReplaySource::rebuild() {
  moves_.clear();
  callTraced_ = false;
  divergence_.reset();
  pictureDivergence_.reset();
  contactEvents_.clear();
  primed_ = false;
  if (replay_.frames() == 0) return;
  const std::uint64_t from = frame_ > history_ ? frame_ - history_ : 0;
  // The world is rebuilt at the keyframe before the history and replayed from there: each call
  // on the way is stepped and compared (a seek would replay them unchecked), so that a
  // divergence anywhere under the picture is known, not only one in the frame on screen.
  if (exact()) {
    const std::uint64_t start = replay_.seekStart(from);
    if (start < from) replay_.seek(start, 0);
    for (std::uint64_t f = start; f < from; ++f) {
      if (replay_.frame() != f || replay_.call() != 0) replay_.seek(f, 0);
      for (std::uint32_t k = 0, n = replay_.callCount(f); k < n; ++k) {
        std::optional<Divergence> d = replay_.step();
        if (d && !pictureDivergence_) pictureDivergence_ = std::move(d);
      }
    }
  }
  for (std::uint64_t f = from; f <= frame_; ++f) {
    const std::vector<CallInfo> here = f == frame_ ? calls_ : replay_.calls(f);
    stepFrame(f, here, f == frame_ && call_ ? *call_ + 1 : here.size());
  }
  trimHistory();
  primed_ = !call_;
}

void ReplaySource::stepFrame(std::uint64_t f, const std::vector<CallInfo>& here,
                                 std::size_t end) {
  // Stepping a frame's last call leaves the replay at the next frame's start (or at the end of
  // the one it stepped): either is the same world. From the end of the frame before, step on
  // into this one: a seek would rebuild the world at a keyframe, and the replay's contacts
  // would forget their history (a ground's velocity, an end).
  const bool onFromBefore = f > 0 && replay_.frame() + 1 == f &&
                            replay_.call() >= replay_.callCount(f - 1) && !replay_.atEnd();
  if (!onFromBefore && (replay_.frame() != f || replay_.call() != 0)) replay_.seek(f, 0);
  for (std::size_t k = 0; k < end; ++k) {
    const CallInfo& c = here[k];
    const bool isCall = f == frame_ && call_ && k == *call_;
    const bool traced =
        traces(c) && (isCall || (selected_ && c.item.valid() && c.item == *selected_));
    MoveTrace t;
    std::optional<Divergence> d = replay_.step(traced ? &t : nullptr);
    if (replay_.frame() == f && replay_.call() == k) {
      // The step only entered the frame, reporting that its keyframe differs from the world:
      // that divergence is this frame's, and the call is the next step.
      if (d && exact() && !pictureDivergence_) pictureDivergence_ = d;
      if (d && f == frame_ && !divergence_) divergence_ = std::move(d);
      d = replay_.step(traced ? &t : nullptr);
    }
    if (d && exact() && !pictureDivergence_) pictureDivergence_ = d;
    // The frame on screen's own, for the inspector's call.
    if (d && f == frame_ && !divergence_) divergence_ = std::move(d);
    if (traced) {
      t.mover = *moverNames_.emplace(t.mover).first;
      moves_.push_back({f, std::move(t)});
      callTraced_ = isCall;
    }
    if (c.kind == CallKind::contacts) noteContacts(f, c);
  }
}

void ReplaySource::noteContacts(std::uint64_t f, const CallInfo& c) {
  // A what-if's world is not the one the game's events came from: it shows none.
  if (!exact()) return;
  sawContacts_ = true;
  if (f != frame_) return;
  const World& w = replay_.world();
  const Rect at = w.has(c.item) ? w.rect(c.item) : Rect{};
  for (const ContactEvent& e : c.contacts)
    contactEvents_.push_back({0, e, at, w.has(e.other) ? w.rect(e.other) : at});
}

std::optional<Ground> ReplaySource::ground(ItemId id) const {
  // The replay stands where the picture was drawn: its tracker's ground is the picture's.
  return exact() ? replay_.ground(id) : std::nullopt;
}

void ReplaySource::trimHistory() {
  // The history covers the last few frames, and at most so many moves, oldest dropped first.
  constexpr std::size_t kKeep = 16;
  const std::uint64_t from = frame_ > history_ ? frame_ - history_ : 0;
  std::size_t drop = 0;
  while (drop < moves_.size() && moves_[drop].tick < from) ++drop;
  if (moves_.size() - drop > kKeep) drop = moves_.size() - kKeep;
  moves_.erase(moves_.begin(), moves_.begin() + static_cast<std::ptrdiff_t>(drop));
}

bool ReplaySource::traces(const CallInfo& c) const {
  if (tracesAMove(c.kind)) return true;
  const ReplayOptions& o = replay_.options();
  return c.kind == CallKind::update && o.mover && o.updatesAsMoves;
}

const MoveTrace* ReplaySource::callTrace() const {
  return callTraced_ && !moves_.empty() ? &moves_.back().trace : nullptr;
}

std::optional<ItemId> ReplaySource::findLabel(std::string_view label) const {
  for (const RecordedItem& i : replay_.items()) {
    if (i.label == label) return i.id;
  }
  return std::nullopt;
}

bool ReplaySource::moves(ItemId id) const {
  const auto at = recorded_.find(id);
  if (at == recorded_.end()) return false;
  const RecordedItem& i = replay_.items()[at->second];
  return i.moves > 0 || i.updates > 0;  // a body the game moves by updates moves too
}

WorldPicture ReplaySource::picture() {
  solids_.clear();
  bodies_.clear();
  bodyFills_.clear();
  std::optional<std::size_t> selectedBody;
  world().forEachItem([&](ItemId id, const Rect& r) {
    const bool isSelected = selected_ && *selected_ == id;
    const auto at = recorded_.find(id);
    const RecordedItem* item = at != recorded_.end() ? &replay_.items()[at->second] : nullptr;
    const bool moving = item != nullptr && (item->moves > 0 || item->updates > 0);
    // An item that never moves is level geometry, unless the game said what it is: an enemy
    // that stands and shoots is drawn as a body, in its category's colour.
    const bool named = item != nullptr && !item->category.empty() && item->category != terrain_;
    if (moving || isSelected || named) {
      if (isSelected) selectedBody = bodies_.size();
      sim::Body b;
      b.item = id;
      b.rect = r;
      bodies_.push_back(b);
      bodyFills_.push_back(!moving && named ? palette::categoryColour(item->category) : 0);
    } else {
      solids_.push_back({r, 0});
    }
  });
  // The corner corrections of the frame on screen, up to the selected call: the recording's
  // cornerNudge calls, drawn as a scene's nudges are (the body where it met the corner, and
  // where the nudge put it).
  nudges_.clear();
  const std::size_t end = call_ ? *call_ + 1 : calls_.size();
  for (std::size_t k = 0; k < end && k < calls_.size(); ++k) {
    const CallInfo& c = calls_[k];
    if (c.kind != CallKind::cornerNudge) continue;
    sim::CornerNudgeAt n;
    n.body = bodies_.size();  // the body drawn for it, if any (else one past the last)
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      if (bodies_[b].item == c.item) n.body = b;
    }
    n.ceiling = c.nudge.hit.other;
    n.from = c.start;
    n.to = c.start.at(c.position);
    nudges_.push_back(n);
  }
  WorldPicture p;
  p.world = &world();
  p.solids = solids_;
  p.bodies = bodies_;
  p.bodyFills = bodyFills_;
  p.nudges = nudges_;
  p.selected = selectedBody;
  p.moves = moves_;
  p.contactEvents = contactEvents_;
  return p;
}

Rect ReplaySource::home() const {
  std::optional<Rect> box;
  world().forEachItem([&](ItemId, const Rect& r) { box = box ? unite(*box, r) : r; });
  if (!box) return {0, 0, 256, 256};
  const double pad = std::max({box->w, box->h, 1.0}) * 0.05;
  return {box->x - pad, box->y - pad, box->w + 2 * pad, box->h + 2 * pad};
}

double ReplaySource::typicalSize() const {
  double best = std::numeric_limits<double>::infinity();
  world().forEachItem([&](ItemId id, const Rect& r) {
    if (moves(id)) best = std::min({best, r.w, r.h});
  });
  if (best == std::numeric_limits<double>::infinity()) {
    world().forEachItem([&](ItemId, const Rect& r) { best = std::min({best, r.w, r.h}); });
  }
  return best == std::numeric_limits<double>::infinity() ? 16.0 : best;
}


double ReplaySource::followMinSide() const {
  return std::max(8.0 * typicalSize(), 64.0);
}

std::string ReplaySource::moverName() const {
  const ReplayOptions& o = replay_.options();
  return o.mover ? o.mover->name() : std::string("recorded");
}

std::unique_ptr<ReplaySource> ReplaySource::whatIf(const MoverSpec& mover,
                                                   bool updatesAsMoves) const {
  ReplayOptions o;
  o.mover = mover;
  o.updatesAsMoves = updatesAsMoves;
  o.tolerant = true;
  const std::string base = name_.substr(0, name_.find(" with "));
  std::unique_ptr<ReplaySource> s;
  if (origin_.bytes) {
    s = fromBytes(origin_.bytes, base + " with " + mover.name(), kind_, o);
  } else {
    s = std::make_unique<ReplaySource>(Replay::open(origin_.path, o), base + " with " + mover.name(),
                                       origin_, kind_);
  }
  return s;
}

std::unique_ptr<Source> ReplaySource::rerun(const MoverSpec& mover) const {
  return whatIf(mover, replay_.options().updatesAsMoves);
}

std::vector<ItemRow> ReplaySource::items() const {
  std::vector<ItemRow> rows;
  rows.reserve(replay_.items().size());
  for (const RecordedItem& i : replay_.items()) {
    ItemRow r;
    r.id = i.id;
    r.name = i.label;
    r.category = i.category;
    r.moves = i.moves > 0 || i.updates > 0;
    r.moveCount = i.moves;
    r.hits = i.hits;
    r.firstFrame = i.firstFrame;
    r.lastFrame = i.lastFrame;
    rows.push_back(std::move(r));
  }
  return rows;
}

std::vector<std::string> ReplaySource::notes() const {
  const auto w = replay_.warnings();
  std::vector<std::string> out(w.begin(), w.end());
  if (std::string label = pictureLabel(); !label.empty()) out.push_back(std::move(label));
  return out;
}

std::string ReplaySource::pictureLabel() const {
  if (divergence_ && exact()) return ui::pictureLabel(*divergence_, true);
  if (pictureDivergence_) return ui::pictureLabel(*pictureDivergence_, false);
  return {};
}

}  // namespace tv::ui
