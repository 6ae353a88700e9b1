// The still picture of a recording, shared by tv-render --open and tv-debugger FILE.tvrec.
#include "tv/ui/recording_still.hpp"

#include <algorithm>
#include <filesystem>
#include <string_view>

#include "tv/app/flags.hpp"
#include "tv/app/movers.hpp"
#include "tv/error.hpp"
#include "tv/ui/still.hpp"

namespace tv::ui {

namespace {

bool endsWith(std::string_view s, std::string_view tail) {
  return s.size() >= tail.size() && s.substr(s.size() - tail.size()) == tail;
}

}  // namespace

std::optional<RecordingFlags> extractRecordingFlags(int argc, char** argv, bool positional,
                                                    std::vector<char*>& rest) {
  RecordingFlags r;
  bool named = false;
  const char* picked = nullptr;  // a recording-only flag, for the error without a file
  const char* placed = nullptr;  // --frame or --call, which --first-failure replaces
  rest.assign(argv, argv + std::min(argc, 1));
  const auto value = [&](int& i, std::string_view flag) -> std::string_view {
    if (i + 1 >= argc || std::string_view(argv[i + 1]).substr(0, 2) == "--")
      throw UsageError{std::string(flag) + " needs a value"};
    return argv[++i];
  };
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--open") {
      if (named) throw UsageError{"--open: one recording at a time"};
      r.path = value(i, arg);
      named = true;
    } else if (arg == "--frame") {
      r.frame = app::parseWhole<UsageError>("frame", value(i, arg));
      picked = placed = "--frame";
    } else if (arg == "--item") {
      r.item = std::string(value(i, arg));
      picked = "--item";
    } else if (arg == "--call") {
      const std::uint64_t k = app::parseWhole<UsageError>("call", value(i, arg));
      if (k > 0xFFFFFFFEu) throw UsageError{"--call: " + std::to_string(k) + " is too large"};
      r.call = static_cast<std::uint32_t>(k);
      picked = placed = "--call";
    } else if (arg == "--what-if") {
      r.whatIf = app::parseMoverFlag<UsageError>("what-if", value(i, arg));
      picked = "--what-if";
    } else if (arg == "--updates-as-moves") {
      r.updatesAsMoves = true;
      picked = "--updates-as-moves";
    } else if (arg == "--first-failure") {
      r.firstFailure = true;
      picked = "--first-failure";
    } else if (positional && arg.substr(0, 1) != "-" && endsWith(arg, ".tvrec")) {
      if (named) throw UsageError{"'" + std::string(arg) + "': one recording at a time"};
      r.path = arg;
      named = true;
    } else {
      rest.push_back(argv[i]);
    }
  }
  if (!named) {
    if (picked) throw UsageError{std::string(picked) + ": only with a recording (--open FILE)"};
    return std::nullopt;
  }
  if (!r.whatIf && (r.updatesAsMoves || r.firstFailure)) {
    throw UsageError{std::string(r.firstFailure ? "--first-failure" : "--updates-as-moves") +
                     ": goes with --what-if MOVER (the re-run it is about)"};
  }
  if (r.firstFailure && placed) {
    throw UsageError{std::string(placed) +
                     ": --first-failure picks the frame and call (of the first re-run move that "
                     "tunnelled or ended inside a solid)"};
  }
  return r;
}

void rejectSceneFlags(const PictureOptions& o) {
  const auto no = [](const std::string& flag) {
    throw UsageError{flag +
                     ": a recording has no scene, mover or tick (it shows frames: "
                     "--frame N, --call K, --item LABEL)"};
  };
  if (o.sceneGiven) no("--scene");
  if (o.moverGiven) no(o.compare ? "--compare" : "--mover");
  if (o.tickGiven) no("--tick");
  if (o.renderHz != 0.0) no("--render-hz");
  if (!o.params.empty()) no("--" + o.params.front().first);
}

RecordingSession openRecording(const std::string& path) {
  ReplayOptions options;
  // The debugger opens what can be opened; the bad chunk's error is a warning of the replay.
  options.tolerant = true;
  return RecordingSession(Replay::open(path, options),
                          std::filesystem::path(path).filename().string());
}

Overlays recordingOverlays(const PictureOptions& o) {
  Overlays on = overlaysFor(o);
  // A recording has no render rate: physics, render and pixel positions coincide, so the
  // three-way marker only adds clutter unless asked for.
  if (std::find(o.show.begin(), o.show.end(), "positions") == o.show.end()) on.positions = false;
  return on;
}

Rect recordingView(const RecordingSession& s, const PictureOptions& o) {
  switch (o.view) {
    case ViewKind::scene:
      return s.bounds();
    case ViewKind::rect:
      return {o.viewRect[0], o.viewRect[1], o.viewRect[2], o.viewRect[3]};
    case ViewKind::follow:
      return s.followView(std::max(8.0 * s.typicalSize(), 64.0));
  }
  return s.bounds();
}

RecordingStill::RecordingStill(const RecordingFlags& r, const PictureOptions& o)
    : r_(r), o_(o), session_(openRecording(r.path)) {
  rejectSceneFlags(o);
  (void)overlaysFor(o);  // a bad --hide/--show fails before anything is drawn
  if (session_.frames() == 0)
    throw UsageError{"--open " + r.path + ": the recording has no frames"};
  if (r.whatIf) {
    // The whole re-run first: its report is part of the picture, and --first-failure needs it.
    whatIf_ = std::make_unique<WhatIf>();
    whatIf_->mover = *r.whatIf;
    whatIf_->report = runWhatIf(r.path, whatIf_->mover, r.updatesAsMoves);
    ReplayOptions ro;
    ro.mover = whatIf_->mover;
    ro.updatesAsMoves = r.updatesAsMoves;
    ro.tolerant = true;
    whatIf_->session = std::make_unique<RecordingSession>(
        Replay::open(r.path, ro), session_.name() + " with " + whatIf_->mover.name());
    if (r.firstFailure) {
      const auto f = firstFailure(whatIf_->report);
      if (!f) {
        throw NoFailure{"under " + moverLabel(whatIf_->mover) + " no move of " + session_.name() +
                        " tunnelled or ended inside a solid (" +
                        std::to_string(whatIf_->report.moves) + " moves re-run)"};
      }
      r_.frame = f->frame;
      r_.call = f->call;
      failedItem_ = f->item;
    }
  }
  showBoth();
}

void RecordingStill::showBoth() {
  RecordingSession* sessions[2] = {&session_, whatIf_ ? whatIf_->session.get() : nullptr};
  for (RecordingSession* s : sessions) {
    if (!s) continue;
    if (r_.frame > s->lastFrame()) {
      throw UsageError{"--frame " + std::to_string(r_.frame) + ": the recording has frames 0.." +
                       std::to_string(s->lastFrame())};
    }
    s->goTo(r_.frame);
    if (r_.item) {
      const auto id = s->findLabel(*r_.item);
      if (!id) throw UsageError{"--item: no recorded item is labelled '" + *r_.item + "'"};
      s->select(id);
    } else if (failedItem_) {
      s->select(failedItem_);
    }
    if (r_.call) {
      if (*r_.call >= s->calls().size()) {
        throw UsageError{"--call " + std::to_string(*r_.call) + ": frame " +
                         std::to_string(r_.frame) + " has " + std::to_string(s->calls().size()) +
                         " calls"};
      }
      s->selectCall(r_.call);
    }
  }
}

void RecordingStill::beginImage() {
  state_ = RecordingViewState{};
  state_.view.overlays = recordingOverlays(o_);
  state_.view.frameView = recordingView(session_, o_);
  state_.view.paused = true;
  state_.revealCall = true;
  if (whatIf_) {
    // One camera for both runs; following frames the recorded move and the re-run's together.
    if (o_.view == ViewKind::follow) {
      const double minSide = std::max(8.0 * session_.typicalSize(), 64.0);
      state_.view.frameView =
          unite(session_.followView(minSide), whatIf_->session->followView(minSide));
    }
    whatIf_->view = DebuggerState{};
    whatIf_->view.overlays = state_.view.overlays;
    whatIf_->view.frameView = state_.view.frameView;
    whatIf_->view.paused = true;
  }
}

void RecordingStill::drawFrame(ImVec2 display) {
  ImGui::SetWindowFocus(nullptr);  // a still has no focused window: no highlighted title
  if (!whatIf_) {
    (void)recordingLayout(session_, state_, {0, 0}, display);
    return;
  }
  WhatIfPair pair{session_, state_, *whatIf_->session, whatIf_->view, whatIf_->mover,
                  r_.updatesAsMoves};
  (void)whatIfLayout(pair, WhatIfStatus{&whatIf_->report, false, {}}, {0, 0}, display);
}

}  // namespace tv::ui
