// The still picture shared by tv-render and tv-debugger's screenshot mode, for every source.
#include "tv/ui/still.hpp"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <string_view>

#include "tv/app/flags.hpp"
#include "tv/app/movers.hpp"
#include "tv/app/user_message.hpp"
#include "tv/app/work_limit.hpp"
#include "tv/error.hpp"
#include "tv/mover.hpp"
#include "tv/ui/checks.hpp"
#include "tv/ui/replay_source.hpp"
#include "tv/ui/sim_source.hpp"
#include "tv/ui/tick_progress.hpp"

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
    // A recording given to --map or --scene-file: the file is right, the flag is not (it read as
    // the recording, leaving "--map needs a value").
    if ((arg == "--map" || arg == "--scene-file") && i + 1 < argc &&
        std::string_view(argv[i + 1]).substr(0, 1) != "-" && endsWith(argv[i + 1], ".tvrec")) {
      const std::string file = argv[i + 1];
      throw UsageError{std::string(arg) + ": '" + file + "' is a recording, not a " +
                       (arg == "--map" ? "map" : "scene file") + ": open it with " +
                       (positional ? "`tv-debugger " + file + "`" : "--open " + file)};
    }
    if (arg == "--open") {
      if (named) throw UsageError{"--open: one recording at a time"};
      r.path = value(i, arg);
      named = true;
    } else if (arg == "--frame") {
      r.frame = app::parseWhole<UsageError>("frame", value(i, arg));
      picked = "--frame";
      r.placedBy = picked;
    } else if (arg == "--item") {
      r.item = std::string(value(i, arg));
      picked = "--item";
    } else if (arg == "--call") {
      const std::uint64_t k = app::parseWhole<UsageError>("call", value(i, arg));
      if (k > 0xFFFFFFFEu) throw UsageError{"--call: " + std::to_string(k) + " is too large"};
      r.call = static_cast<std::uint32_t>(k);
      picked = "--call";
      r.placedBy = picked;
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
  if (r.updatesAsMoves && !r.whatIf)
    throw UsageError{"--updates-as-moves: goes with --what-if MOVER (the re-run it is about)"};
  return r;
}

void checkFirstFailure(const PictureOptions& o, const std::optional<RecordingFlags>& r) {
  if (!o.firstFailure) return;
  std::string placed = r ? r->placedBy : std::string();
  if (placed.empty() && o.tickGiven) placed = o.ticks.size() > 1 ? "--ticks" : "--tick";
  if (!placed.empty()) {
    throw UsageError{placed + ": --first-failure picks the " + (r ? "frame and call" : "tick") +
                     " (of the run's first failure)"};
  }
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

const sim::SceneDef& sceneFor(const PictureOptions& o) {
  if (o.file.given()) return o.file.scene();  // tv::Error naming the file, path and value
  if (const sim::SceneDef* s = sim::builtinScenes().tryFind(o.scene)) return *s;
  std::string valid;
  for (const std::string_view n : sim::builtinScenes().names()) {
    valid += (valid.empty() ? "" : ", ") + std::string(n);
  }
  throw UsageError{"--scene: no scene is named '" + o.scene + "'; valid: " + valid};
}

sim::Params paramsFor(const sim::SceneDef& scene, const PictureOptions& o) {
  sim::Params p = scene.defaults();
  for (const auto& [name, text] : o.params) {
    const std::string flag = "--" + name;
    if (!p.has(name)) {
      std::string valid;
      for (const std::string_view n : p.names())
        valid += (valid.empty() ? "--" : ", --") + std::string(n);
      throw UsageError{flag + ": neither a flag nor a parameter of scene '" + scene.name +
                       "' (its parameters: " + valid + ")"};
    }
    // Read as every tool reads a number (tv/app/flags.hpp): the same message everywhere.
    const double v = app::parseFinite<UsageError>(name, text);
    try {
      p.set(name, v);
    } catch (const Error& e) {
      throw UsageError{flag + " " + text + ": " + app::userMessage(e)};
    }
  }
  return p;
}

Overlays overlaysFor(const PictureOptions& o, bool recording) {
  Overlays on;
  const auto apply = [&](const std::vector<std::string>& names, bool value, const char* flag) {
    for (const std::string& n : names) {
      bool found = n == "all";
      for (const OverlayToggle& t : overlayToggles()) {
        if (found && n == "all") on.*t.flag = value;
        if (n == t.name) {
          on.*t.flag = value;
          found = true;
        }
      }
      if (!found) {
        std::string valid;
        for (const OverlayToggle& t : overlayToggles()) valid += std::string(" ") + t.name;
        throw UsageError{std::string(flag) + ": no overlay is named '" + n + "'; valid: all" +
                         valid};
      }
    }
  };
  // A recording has no render rate: physics, render and pixel positions coincide, so the
  // three-way marker only adds clutter unless asked for.
  if (recording) on.positions = false;
  apply(o.hide, false, "--hide");
  apply(o.show, true, "--show");
  return on;
}

std::vector<std::unique_ptr<Source>> sceneSources(const PictureOptions& o) {
  const sim::SceneDef& scene = sceneFor(o);
  const sim::Params params = paramsFor(scene, o);
  const SourceKind kind = o.file.given() ? SourceKind::level : SourceKind::scene;
  std::vector<std::unique_ptr<Source>> out;
  for (const MoverSpec& spec : o.movers) {
    std::unique_ptr<SimSource> s;
    try {
      s = std::make_unique<SimSource>(scene, params, spec, kind);
    } catch (const Error& e) {
      throw UsageError{"scene '" + scene.name + "': " + app::userMessage(e)};
    }
    const sim::Simulation& sim = s->simulation();
    if (auto why = app::workLimitExceeded(params, sim.moverSpec(), sim.bodies().size()))
      throw UsageError{*why};
    try {
      s->traceBody(o.body);
    } catch (const Error& e) {
      throw UsageError{"--body: " + app::userMessage(e)};
    }
    s->setRenderHz(o.renderHz);
    if (o.file.given()) s->setNotes(o.file.notes());
    out.push_back(std::move(s));
  }
  return out;
}

void showRecorded(Session& session, const RecordingFlags& r) {
  const ReplaySource* replay = session.primary().replay();
  if (!replay) throw UsageError{"--frame: only with a recording"};
  if (replay->frames() == 0) throw UsageError{"--open " + r.path + ": the recording has no frames"};
  if (r.frame > replay->lastFrame()) {
    throw UsageError{"--frame " + std::to_string(r.frame) + ": the recording has frames 0.." +
                     std::to_string(replay->lastFrame())};
  }
  session.goTo(r.frame);
  if (r.item) {
    const auto id = replay->findLabel(*r.item);
    if (!id) throw UsageError{"--item: no recorded item is labelled '" + *r.item + "'"};
    session.trace(id);
  }
  if (r.call) {
    if (*r.call >= session.calls().size()) {
      throw UsageError{"--call " + std::to_string(*r.call) + ": frame " + std::to_string(r.frame) +
                       " has " + std::to_string(session.calls().size()) + " calls"};
    }
    session.selectCall(r.call);
  }
}

Still::Still(const PictureOptions& o, const std::optional<RecordingFlags>& r)
    : o_(o), recorded_(r) {
  (void)overlaysFor(o);  // a bad --hide/--show fails before anything runs
  checkFirstFailure(o, r);
  if (r) {
    rejectSceneFlags(o);
    // The recorded run, and a what-if re-run beside it, as the debugger opens them.
    std::unique_ptr<ReplaySource> recorded = ReplaySource::open(r->path);
    std::unique_ptr<Source> whatIf;
    if (r->whatIf) whatIf = recorded->whatIf(*r->whatIf, r->updatesAsMoves);
    session_ = std::make_unique<Session>(std::move(recorded));
    showRecorded(*session_, *r);
    if (whatIf) {
      std::vector<std::unique_ptr<Source>> others;
      others.push_back(std::move(whatIf));
      session_->compareWith(std::move(others));
    }
  } else {
    session_ = std::make_unique<Session>(sceneSources(o));
  }
  if (o.firstFailure || (r && r->whatIf)) findFailures();
}

void Still::findFailures() {
  // The debugger's own checks, run to the end here: the same list its Failures tab shows.
  Checks checks;
  checks.reset(*session_, true);
  checks.advance(1e300);
  failures_ = checks.failures();
  checked_ = true;
  if (!o_.firstFailure) return;
  shown_ = firstFailureIndex(failures_);
  if (!shown_) {
    // A scene's looked-at count is of ticks run; a recording's, the last frame's index.
    const std::uint64_t looked = failures_.looked + (session_->primary().sim() ? 0 : 1);
    std::string what = session_->primary().name();
    if (session_->comparing()) {
      std::string movers;
      for (std::size_t k = 0; k < session_->size(); ++k)
        movers += (movers.empty() ? "" : ", ") + session_->panel(k).moverName();
      what += " (" + movers + ")";
    }
    throw NoFailure{"no move of " + what + " failed in " + std::to_string(looked) + " " +
                    frameWord(session_->primary()) + "s"};
  }
  // The session goes there now; the view (framing, inspector, the marked row) at beginImage.
  ViewState v;
  v.failures = failures_;
  goToFailure(*session_, v, *shown_);
}

Still::~Still() = default;

void Still::advanceTo(std::uint64_t tick, const char* tool) {
  if (recorded_ || shown_) return;
  TickProgress progress(tool, "--tick " + std::to_string(tick));
  TickProgress::attach(*session_, &progress);
  struct Detach {
    Session& s;
    ~Detach() { TickProgress::attach(s, nullptr); }
  } detach{*session_};
  try {
    // First as far as the scene goes: a tick after every mover's end is refused, not run for
    // ever; a mover that ended early then runs on to the tick the others reach.
    std::uint64_t reached = 0;
    for (std::size_t k = 0; k < session_->size(); ++k) {
      SimSource& s = *session_->panel(k).sim();
      s.advanceTo(tick, o_.renderHz, true);
      reached = std::max(reached, s.frame());
    }
    if (reached < tick) {
      throw UsageError{"--tick " + std::to_string(tick) + ": the scene ends at tick " +
                       std::to_string(reached)};
    }
    for (std::size_t k = 0; k < session_->size(); ++k)
      session_->panel(k).sim()->advanceTo(tick, o_.renderHz);
  } catch (const UsageError&) {
    throw;
  } catch (const Error& e) {
    throw UsageError{"--tick " + std::to_string(tick) + ": " + app::userMessage(e)};
  }
}

void Still::beginImage() {
  Rect frame = session_->primary().home();
  switch (o_.view) {
    case ViewKind::scene:
      break;
    case ViewKind::rect:
      frame = {o_.viewRect[0], o_.viewRect[1], o_.viewRect[2], o_.viewRect[3]};
      break;
    case ViewKind::follow:
      // One rect for every panel, so the movers are compared over the same ground.
      frame = session_->followView();
      break;
  }
  view_ = ViewState{};
  syncPanels(view_, *session_);
  for (std::size_t k = 0; k < session_->size(); ++k) {
    DebuggerState& st = view_.panels[k];
    st.overlays = overlaysFor(o_, recorded_.has_value());
    st.frameView = frame;
    st.paused = true;  // a still is a paused frame
    if (const SimSource* sim = session_->panel(k).sim()) syncDraft(st, *sim);
  }
  view_.revealCall = true;
  view_.caption = o_.compare ? o_.caption : "";
  if (checked_) {
    view_.failures = failures_;
  } else {
    view_.failures.note = "the debugger lists every failure of the run";
    view_.failures.complete = true;
  }
  if (shown_) {
    // The first failure, as "go" shows it: the failing panel inspected, its row marked, every
    // panel framed on the failing move unless --view names a rect.
    const Rect keep = frame;
    goToFailure(*session_, view_, *shown_);
    if (o_.view == ViewKind::rect) {
      for (DebuggerState& st : view_.panels) st.frameView = keep;
    }
  }
}

void Still::drawFrame(ImVec2 display) {
  ImGui::SetWindowFocus(nullptr);  // a still has no focused window: no highlighted title
  (void)sessionView(*session_, view_, {0, 0}, display);
}

}  // namespace tv::ui
