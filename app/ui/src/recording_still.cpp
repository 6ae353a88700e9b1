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
      picked = "--frame";
    } else if (arg == "--item") {
      r.item = std::string(value(i, arg));
      picked = "--item";
    } else if (arg == "--call") {
      const std::uint64_t k = app::parseWhole<UsageError>("call", value(i, arg));
      if (k > 0xFFFFFFFEu) throw UsageError{"--call: " + std::to_string(k) + " is too large"};
      r.call = static_cast<std::uint32_t>(k);
      picked = "--call";
    } else if (arg == "--what-if") {
      r.whatIf = app::parseMoverFlag<UsageError>("what-if", value(i, arg));
      picked = "--what-if";
    } else if (arg == "--updates-as-moves") {
      r.updatesAsMoves = true;
      picked = "--updates-as-moves";
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
  if (r.whatIf || r.updatesAsMoves) {
    throw UsageError{
        std::string(r.whatIf ? "--what-if" : "--updates-as-moves") +
        ": a what-if run is shown by tv-debugger (tv-replay --mover prints its report)"};
  }
  (void)overlaysFor(o);  // a bad --hide/--show fails before anything is drawn
  if (session_.frames() == 0)
    throw UsageError{"--open " + r.path + ": the recording has no frames"};
  if (r.frame > session_.lastFrame()) {
    throw UsageError{"--frame " + std::to_string(r.frame) + ": the recording has frames 0.." +
                     std::to_string(session_.lastFrame())};
  }
  session_.goTo(r.frame);
  if (r.item) {
    const auto id = session_.findLabel(*r.item);
    if (!id) throw UsageError{"--item: no recorded item is labelled '" + *r.item + "'"};
    session_.select(id);
  }
  if (r.call) {
    if (*r.call >= session_.calls().size()) {
      throw UsageError{"--call " + std::to_string(*r.call) + ": frame " + std::to_string(r.frame) +
                       " has " + std::to_string(session_.calls().size()) + " calls"};
    }
    session_.selectCall(r.call);
  }
}

void RecordingStill::beginImage() {
  state_ = RecordingViewState{};
  state_.view.overlays = recordingOverlays(o_);
  state_.view.frameView = recordingView(session_, o_);
  state_.view.paused = true;
  state_.revealCall = true;
}

void RecordingStill::drawFrame(ImVec2 display) {
  ImGui::SetWindowFocus(nullptr);  // a still has no focused window: no highlighted title
  (void)recordingLayout(session_, state_, {0, 0}, display);
}

}  // namespace tv::ui
