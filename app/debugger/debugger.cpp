// The debugger's model: sessions in lockstep, time travel, tuning, selection, commands.
#include "debugger.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>

#include "tv/app/user_message.hpp"
#include "tv/app/work_limit.hpp"
#include "tv/error.hpp"
#include "tv/ui/still.hpp"

namespace tv::viewer {

namespace {

constexpr double kMinSpeed = 0.25, kMaxSpeed = 4.0;
// Simulated frames run per drawn frame at most: beyond that the debugger drops time rather
// than fall further behind (a huge scene at 4x).
constexpr int kMaxFramesPerDraw = 16;

std::vector<std::string> splitCommas(const std::string& s) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= s.size()) {
    const std::size_t comma = s.find(',', start);
    const std::string part = s.substr(start, comma - start);
    if (!part.empty()) out.push_back(part);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

}  // namespace

Debugger::Debugger(const ViewerOptions& options, const Settings* settings) {
  ui::PictureOptions o = options.picture;
  // Saved settings fill in what the command line leaves out.
  std::vector<MoverSpec> movers = o.movers;
  if (settings) {
    if (!o.sceneGiven) {
      if (const auto s = settings->get("scene"); s && sim::builtinScenes().tryFind(*s))
        o.scene = *s;
    }
    if (!o.moverGiven) {
      // Saved names are parsed here, where they were typed (or saved); a hand-edited list with
      // an unknown or repeated name is ignored whole.
      if (const auto m = settings->get("movers")) {
        std::vector<MoverSpec> saved;
        bool valid = true;
        for (const std::string& n : splitCommas(*m)) {
          try {
            const MoverSpec spec = parseMover(n);
            for (const MoverSpec& before : saved) valid = valid && before.name() != spec.name();
            saved.push_back(spec);
          } catch (const Error&) {
            valid = false;
          }
        }
        if (valid && !saved.empty()) movers = std::move(saved);
      }
    }
    overlay_ = settings->getBool("overlay", false);
    follow_ = settings->getBool("follow", false);
    speed_ = std::clamp(settings->getNumber("speed", 1.0), kMinSpeed, kMaxSpeed);
    showHelp_ = !settings->getBool("help.seen", false);
  }
  overlay_ = overlay_ || options.overlay;
  showSweep_ = options.sweep;
  if (o.file.given()) {
    files_.push_back(o.file);
    if (const auto m = o.file.mover(); m && !o.moverGiven) movers = {*m};
    for (const std::string& note : o.file.notes())
      std::fprintf(stderr, "tv-debugger: note: %s\n", note.c_str());
  }
  const sim::SceneDef& scene = ui::sceneFor(o);
  sim::Params params = ui::paramsFor(scene, o);
  // Tuned values come back with their scene, unless the command line sets any parameter.
  if (settings && o.params.empty() && settings->get("params.scene") == scene.name) {
    const sim::Params defaults = scene.defaults();
    for (const sim::ParamSpec& spec : defaults.specs()) {
      try {
        params.set(spec.name, settings->getNumber("param." + spec.name, params.get(spec.name)));
      } catch (const Error&) {
        // A hand-edited value out of range: the default stays.
      }
    }
  }
  const ui::Overlays overlays = ui::overlaysFor(o);
  selected_ = o.body;

  states_.assign(1, ui::DebuggerState{});
  states_[0].overlays = overlays;
  if (settings) {
    for (const ui::OverlayToggle& t : ui::overlayToggles()) {
      // The command line's --hide/--show win over what was saved.
      const bool named = std::find(o.hide.begin(), o.hide.end(), t.name) != o.hide.end() ||
                         std::find(o.show.begin(), o.show.end(), t.name) != o.show.end();
      if (!named)
        states_[0].overlays.*t.flag =
            settings->getBool(std::string("overlay.") + t.name, overlays.*t.flag);
    }
    if (o.renderHz == 0.0) o.renderHz = settings->getNumber("render-hz", 0.0);
  }
  states_[0].renderHz = std::clamp(o.renderHz, 0.0, 1000.0);
  try {
    build(scene, params, std::move(movers), 0);
  } catch (const Error& e) {
    throw ui::UsageError{"scene '" + scene.name + "': " + app::userMessage(e)};
  }
  if (o.body && *o.body >= sessions_.front()->sim().bodies().size()) {
    throw ui::UsageError{"--body: body " + std::to_string(*o.body) +
                         " does not exist (the scene has " +
                         std::to_string(sessions_.front()->sim().bodies().size()) + " bodies)"};
  }
  switch (o.view) {
    case ui::ViewKind::scene:
      break;
    case ui::ViewKind::follow:
      follow_ = true;
      break;
    case ui::ViewKind::rect:
      follow_ = false;
      for (auto& st : states_)
        st.frameView = Rect{o.viewRect[0], o.viewRect[1], o.viewRect[2], o.viewRect[3]};
      break;
  }
  try {
    goTo(o.ticks.front(), true);
    if (tick() < o.ticks.front()) {
      throw ui::UsageError{"--tick " + std::to_string(o.ticks.front()) +
                           ": the scene ends at tick " + std::to_string(tick())};
    }
  } catch (const ui::UsageError&) {
    throw;
  } catch (const Error& e) {
    throw ui::UsageError{"--tick " + std::to_string(o.ticks.front()) + ": " + app::userMessage(e)};
  }
}

void Debugger::store(Settings& s) const {
  s.set("scene", scene_->name);
  std::string names;
  for (const MoverSpec& m : movers_) {
    if (!names.empty()) names += ',';
    names += m.name();
  }
  s.set("movers", names);
  s.setBool("overlay", overlay_);
  s.setBool("follow", follow_);
  s.setNumber("speed", speed_);
  s.setNumber("render-hz", states_[0].renderHz);
  s.setBool("help.seen", true);
  s.set("params.scene", scene_->name);
  for (std::size_t i = 0; i < params_.specs().size(); ++i)
    s.setNumber("param." + params_.specs()[i].name, params_.values()[i]);
  for (const ui::OverlayToggle& t : ui::overlayToggles()) {
    s.setBool(std::string("overlay.") + t.name, states_[0].overlays.*t.flag);
  }
}

// -- sessions --------------------------------------------------------------------------------

void Debugger::build(const sim::SceneDef& scene, const sim::Params& params,
                     std::vector<MoverSpec> movers, std::uint64_t landOn) {
  // Everything is built first, so a rejected combination changes nothing.
  std::vector<std::unique_ptr<ui::Session>> sessions;
  for (const MoverSpec& m : movers) {
    sessions.push_back(std::make_unique<ui::Session>(scene, params, m, std::nullopt));
    const sim::Simulation& s = sessions.back()->sim();
    // A tick that would take seconds is refused here, before anything runs (and freezes).
    if (auto why = app::workLimitExceeded(params, s.moverSpec(), s.bodies().size()))
      throw Error(*why);
  }
  const std::size_t bodies = sessions.front()->sim().bodies().size();
  if (selected_ && *selected_ >= bodies)
    selected_ = bodies > 0 ? std::optional<std::size_t>(0) : std::nullopt;
  for (auto& s : sessions) s->select(selected_);

  const bool sameScene = scene_ == &scene;
  scene_ = &scene;
  params_ = params;
  movers_ = std::move(movers);
  sessions_ = std::move(sessions);
  const ui::DebuggerState primary = states_.empty() ? ui::DebuggerState{} : states_.front();
  states_.resize(sessions_.size(), primary);
  for (std::size_t k = 0; k < sessions_.size(); ++k) {
    states_[k].overlays = primary.overlays;
    states_[k].renderHz = primary.renderHz;
    if (!sameScene) {
      states_[k].frameView = sessions_[k]->sim().camera();
      states_[k].error.clear();
    }
    ui::syncDraft(states_[k], *sessions_[k]);
  }
  inspected_ = std::min(inspected_, sessions_.size() - 1);
  divergence_.reset(scene, params, movers_);
  clock_ = 0.0;
  furthest_ = landOn;
  // How long a re-run to this tick takes decides whether sliders follow live.
  const auto t0 = std::chrono::steady_clock::now();
  goTo(landOn);
  const std::chrono::duration<double, std::milli> spent = std::chrono::steady_clock::now() - t0;
  states_[0].lastRerunMs = spent.count();
}

void Debugger::loadScene(const sim::SceneDef& scene) {
  try {
    build(scene, scene.defaults(), movers_, 0);
    message_.clear();
  } catch (const Error& e) {
    reportError("scene '" + scene.name + "': " + app::userMessage(e));
  }
}

void Debugger::openFile(const std::string& path) {
  const app::SceneSource file = app::SceneSource::forFile(path);
  try {
    const sim::SceneDef& scene = file.scene();  // throws naming the file, JSON path and value
    files_.push_back(file);
    build(scene, scene.defaults(), movers_, 0);
    furthest_ = 0;
    message_.clear();
    for (const std::string& note : file.notes()) reportError(note);
  } catch (const Error& e) {
    reportError(app::userMessage(e));
  }
}

void Debugger::setMovers(std::vector<MoverSpec> movers) {
  if (movers.empty()) return;
  try {
    build(*scene_, params_, std::move(movers), tick());
  } catch (const Error& e) {
    reportError(app::userMessage(e));
  }
}

std::uint64_t Debugger::tick() const {
  return sessions_.front()->sim().ticks();
}

void Debugger::goTo(std::uint64_t t, bool stopAtEnd) {
  notice_.clear();  // a notice tells of the tick it was given at ("the scene ended at tick 5")
  for (std::size_t k = 0; k < sessions_.size(); ++k) {
    ui::Session& s = *sessions_[k];
    sim::Simulation& sim = s.sim();
    const std::uint64_t h = std::min<std::uint64_t>(s.historyLength(), t);
    const std::uint64_t from = t - h;
    // Older than the ring holds: from tick 0 again (deterministic, so the same states).
    if (from < sim.oldestTick()) s.restart(params_, movers_[k]);
    sim.seek(from);
    s.select(selected_);  // the history starts afresh and is re-traced below
  }
  // In step, so that with stopAtEnd they stop when every mover's scene has ended short of `t`
  // (a mover that ended early otherwise runs on with the others).
  const auto behind = [&] {
    return std::any_of(sessions_.begin(), sessions_.end(),
                       [&](const auto& s) { return s->sim().ticks() < t; });
  };
  const auto ended = [&] {
    return std::all_of(sessions_.begin(), sessions_.end(),
                       [](const auto& s) { return s->sim().finished(); });
  };
  const auto noneThere = [&] {
    return std::none_of(sessions_.begin(), sessions_.end(),
                        [&](const auto& s) { return s->sim().ticks() >= t; });
  };
  while (behind() && !(stopAtEnd && ended() && noneThere())) {
    for (auto& s : sessions_) {
      if (s->sim().ticks() < t) s->tick();
    }
  }
  furthest_ = std::max(furthest_, tick());
  clock_ = 0.0;
}

void Debugger::stepOnce() {
  paused_ = true;
  notice_.clear();
  for (auto& s : sessions_) s->tick();
  furthest_ = std::max(furthest_, tick());
}

void Debugger::advance(double seconds) {
  if (paused_) return;
  clock_ += seconds * speed_;
  const double renderHz = states_[0].renderHz;
  // A render rate draws frames of 1/rate through the accumulator (interpolated); none, ticks.
  const double step = renderHz > 0.0 ? 1.0 / renderHz : sessions_.front()->sim().dt();
  int n = 0;
  while (clock_ >= step && n < kMaxFramesPerDraw) {
    for (auto& s : sessions_) {
      if (renderHz > 0.0) {
        (void)s->frame(step);
      } else {
        s->tick();
      }
    }
    clock_ -= step;
    ++n;
  }
  if (n == kMaxFramesPerDraw) clock_ = 0.0;
  furthest_ = std::max(furthest_, tick());
  // Nothing more can happen: stop, so the interesting ticks stay in the ring.
  const bool finished = std::all_of(sessions_.begin(), sessions_.end(),
                                    [](const auto& s) { return s->sim().finished(); });
  if (finished) {
    paused_ = true;
    notice_ = "the scene ended at tick " + std::to_string(tick()) + " (Play runs it again)";
  }
}

void Debugger::select(std::optional<std::size_t> body) {
  if (body && *body >= sessions_.front()->sim().bodies().size()) return;
  selected_ = body;
  // Re-run the last ticks traced, so the inspector shows the new body's moves at once.
  goTo(tick());
}

Rect Debugger::followRect() const {
  const double minSide =
      4.0 * std::max(params_.get(sim::param::tile), params_.get(sim::param::size));
  Rect r = sessions_.front()->followView(minSide);
  for (const auto& s : sessions_) r = unite(r, s->followView(minSide));
  return r;
}

void Debugger::reportError(const std::string& what) {
  message_ = what;
  states_[0].error = what;
}

void Debugger::applyActions(const ui::Actions& a) {
  if (a.togglePause) run(Command::pause);
  if (a.step) run(Command::stepForward);
  if (a.stepBack) run(Command::stepBack);
  if (a.select) select(a.select);
  if (!a.restart) return;
  ui::DebuggerState& st = states_[0];
  if (st.draftScene != scene_->name) {
    if (const sim::SceneDef* s = sim::builtinScenes().tryFind(st.draftScene)) loadScene(*s);
    return;
  }
  const MoverSpec primary = st.draftMover;
  const bool tuned = primary.name() != movers_.front().name() ||
                     !std::equal(st.draft.values().begin(), st.draft.values().end(),
                                 params_.values().begin(), params_.values().end());
  std::vector<MoverSpec> movers = movers_;
  movers.front() = primary;
  for (std::size_t k = 1; k < movers.size(); ++k) {
    if (movers[k].name() == primary.name()) {
      reportError("mover: " + primary.name() + " is already compared (panel " +
                  std::to_string(k + 1) + ")");
      ui::syncDraft(st, *sessions_.front());
      st.error = message_;
      return;
    }
  }
  try {
    // A tune re-runs from tick 0 and lands on the same tick; a plain restart goes to tick 0.
    build(*scene_, st.draft, std::move(movers), tuned ? tick() : 0);
    if (!tuned) furthest_ = 0;
    message_.clear();
    notice_.clear();
  } catch (const Error& e) {
    // Refused: the panel shows the values that run, with the reason beside them.
    reportError(app::userMessage(e));
    ui::syncDraft(st, *sessions_.front());
    st.error = message_;
  }
}

void Debugger::applyOrDefer(const ui::Actions& a) {
  // A re-run known to be slow is shown as coming ("re-running...") and done on the next frame,
  // so the window says what it is doing before it is busy.
  if (a.restart && states_[0].lastRerunMs >= ui::kLiveRerunMs && !pinned_) {
    ui::Actions now = a;
    now.restart = false;
    applyActions(now);
    deferred_ = true;
    notice_ = "re-running to tick " + std::to_string(tick()) + " (the last re-run took " +
              std::to_string(static_cast<int>(states_[0].lastRerunMs)) + " ms)...";
    return;
  }
  applyActions(a);
}

bool Debugger::tune(const std::string& param, double value) {
  ui::DebuggerState& st = states_[0];
  try {
    st.draft.set(param, value);
  } catch (const Error& e) {
    reportError(app::userMessage(e));
    return false;
  }
  message_.clear();
  ui::Actions a;
  a.restart = true;
  applyActions(a);
  return message_.empty();
}

void Debugger::run(Command c) {
  const auto& all = sim::builtinScenes().all();
  const auto sceneIndex = [&] {
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (&all[i] == scene_) return i;
    }
    return std::size_t{0};
  };
  switch (c) {
    case Command::pause: {
      notice_.clear();
      const bool ended = std::all_of(sessions_.begin(), sessions_.end(),
                                     [](const auto& s) { return s->sim().finished(); });
      // Play on a scene that has ended plays it again, and says so, rather than pausing at once.
      if (paused_ && ended) {
        const std::uint64_t end = tick();
        goTo(0);
        notice_ = "the scene had ended at tick " + std::to_string(end) + ": playing again from 0";
      }
      paused_ = !paused_;
      clock_ = 0.0;
      break;
    }
    case Command::step:
      stepOnce();
      break;
    case Command::stepBack:
      paused_ = true;
      if (tick() > 0) goTo(tick() - 1);
      break;
    case Command::stepForward:
      paused_ = true;
      goTo(tick() + 1);
      break;
    case Command::restart:
      build(*scene_, params_, movers_, 0);
      break;
    case Command::slower:
      speed_ = std::max(kMinSpeed, speed_ * 0.5);
      break;
    case Command::faster:
      speed_ = std::min(kMaxSpeed, speed_ * 2.0);
      break;
    case Command::frameAll:
      follow_ = false;
      for (auto& st : states_) st.frameView = sessions_.front()->sim().camera();
      break;
    case Command::follow:
      follow_ = !follow_;
      if (!follow_) run(Command::frameAll);
      break;
    case Command::compare:
      if (compare()) {
        setMovers({movers_.front()});
      } else {
        setMovers({MoverSpec{.kind = MoverKind::discrete}, MoverSpec{.kind = MoverKind::substep},
                   MoverSpec{.kind = MoverKind::continuous}});
      }
      break;
    case Command::overlay:
      overlay_ = !overlay_;
      break;
    case Command::sweep:
      showSweep_ = !showSweep_;
      break;
    case Command::openScene:
      openPicker_ = true;
      break;
    case Command::previousScene:
      loadScene(all[(sceneIndex() + all.size() - 1) % all.size()]);
      break;
    case Command::nextScene:
      loadScene(all[(sceneIndex() + 1) % all.size()]);
      break;
    case Command::help:
      showHelp_ = !showHelp_;
      break;
    case Command::quit:
      quit_ = true;
      break;
  }
}

// -- recordings ------------------------------------------------------------------------------

RecordingDebugger& Debugger::openRecording(const std::string& path) {
  if (recording_) {
    recording_->reopen(path);
  } else {
    ui::Overlays overlays = states_[0].overlays;
    overlays.positions = false;  // no render rate in a recording: the three positions coincide
    recording_ = std::make_unique<RecordingDebugger>(path, overlays, pinned_);
  }
  return *recording_;
}

void Debugger::tryOpenRecording(const std::string& path) {
  try {
    (void)openRecording(path);
    message_.clear();
  } catch (const std::exception& e) {
    reportError(app::userMessage(e));
  }
}

}  // namespace tv::viewer
