// The debugger's model: opening sources, panels in lockstep, time, selection, tuning, commands.
#include "debugger.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "tv/app/user_message.hpp"
#include "tv/app/work_limit.hpp"
#include "tv/error.hpp"
#include "tv/ui/replay_source.hpp"
#include "tv/ui/sim_source.hpp"
#include "tv/ui/still.hpp"
#include "tv/ui/tick_progress.hpp"
#include "tv/record/live.hpp"
#include "tv/ui/live_source.hpp"

namespace tv::viewer {

namespace {

constexpr double kMinSpeed = 0.25, kMaxSpeed = 4.0;
// Frames played per drawn frame at most: beyond that the debugger drops time rather than fall
// further behind (a huge scene at 4x).
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

// The three movers a first comparison shows: the naive one, the usual patch, the exact sweep.
std::vector<MoverSpec> naivePatchExact() {
  return {MoverSpec{.kind = MoverKind::discrete}, MoverSpec{.kind = MoverKind::substep},
          MoverSpec{.kind = MoverKind::continuous}};
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
    view_.overlaid = settings->getBool("overlay", false);
    follow_ = settings->getBool("follow", false);
    speed_ = std::clamp(settings->getNumber("speed", 1.0), kMinSpeed, kMaxSpeed);
    showHelp_ = !settings->getBool("help.seen", false);
  }
  view_.overlaid = view_.overlaid || options.overlay;
  showSweep_ = options.sweep;

  ui::DebuggerState first;
  first.overlays = ui::overlaysFor(o, options.recording.has_value());
  if (settings) {
    for (const ui::OverlayToggle& t : ui::overlayToggles()) {
      // The command line's --hide/--show win over what was saved.
      const bool named = std::find(o.hide.begin(), o.hide.end(), t.name) != o.hide.end() ||
                         std::find(o.show.begin(), o.show.end(), t.name) != o.show.end();
      if (!named)
        first.overlays.*t.flag = settings->getBool(std::string("overlay.") + t.name, first.overlays.*t.flag);
    }
    if (o.renderHz == 0.0 && !options.recording) o.renderHz = settings->getNumber("render-hz", 0.0);
  }
  first.renderHz = std::clamp(o.renderHz, 0.0, 1000.0);
  view_.panels.assign(1, first);

  if (options.listen) {
    // A live game: what arrives, as it arrives.
    listen(*options.listen, options.keepFrames, options.keepMegabytes);
    view_.showTab = options.tab;
    return;
  }
  if (options.recording) {
    // A recording: the frame, call and item the flags name; a what-if run beside it.
    const ui::RecordingFlags& r = *options.recording;
    openRecording(r.path);
    show(r.frame, r.call, r.item);
    if (r.whatIf) compareWith({*r.whatIf}, r.updatesAsMoves);
  } else {
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
    try {
      buildScene(scene, params, std::move(movers), 0,
                 o.file.given() ? ui::SourceKind::level : ui::SourceKind::scene);
    } catch (const Error& e) {
      throw ui::UsageError{"scene '" + scene.name + "': " + app::userMessage(e)};
    }
    const std::size_t bodies = session_->primary().sim()->simulation().bodies().size();
    if (o.body && *o.body >= bodies) {
      throw ui::UsageError{"--body: body " + std::to_string(*o.body) +
                           " does not exist (the scene has " + std::to_string(bodies) + " bodies)"};
    }
    if (o.body) select(session_->primary().sim()->simulation().bodies()[*o.body].item);
    try {
      // A far tick runs before the window opens: how far it has got is said on stderr.
      ui::TickProgress progress("tv-debugger", "--tick " + std::to_string(o.ticks.front()));
      ui::TickProgress::attach(*session_, &progress);
      goTo(o.ticks.front(), true);
      ui::TickProgress::attach(*session_, nullptr);
      if (currentTick() < o.ticks.front()) {
        throw ui::UsageError{"--tick " + std::to_string(o.ticks.front()) +
                             ": the scene ends at tick " + std::to_string(currentTick())};
      }
    } catch (const ui::UsageError&) {
      throw;
    } catch (const Error& e) {
      throw ui::UsageError{"--tick " + std::to_string(o.ticks.front()) + ": " + app::userMessage(e)};
    }
  }
  view_.showTab = options.tab;
  if (o.firstFailure) {
    // Looked for now, before the window opens: the first frame shown is the failure.
    checks_.reset(*session_, true);
    checks_.advance(1e12);
    run(Command::firstFailure);
    if (checks_.failures().entries.empty()) notice_ = "no failure found in the run";
    if (options.tab) view_.showTab = options.tab;
    return;
  }
  switch (o.view) {
    case ui::ViewKind::scene:
      if (!isScene()) frameAll();
      break;
    case ui::ViewKind::follow:
      follow_ = true;
      break;
    case ui::ViewKind::rect:
      follow_ = false;
      for (auto& st : view_.panels)
        st.frameView = Rect{o.viewRect[0], o.viewRect[1], o.viewRect[2], o.viewRect[3]};
      break;
  }
}

Debugger::~Debugger() = default;

void Debugger::setPinned(bool pinned) {
  pinned_ = pinned;
  // A screenshot's marks must not depend on how fast the machine is: the checks run to the end.
  if (pinned_ && session_) checks_.reset(*session_, true);
}

void Debugger::store(Settings& s) const {
  // What belongs to the person, whatever is open: Help has been seen (it opened on every start
  // of someone who only opens recordings), the playback rate.
  s.setBool("help.seen", true);
  s.setNumber("speed", speed_);
  if (!scene_) return;  // a recording leaves the scene settings as they were
  s.set("scene", scene_->name);
  std::string names;
  for (const MoverSpec& m : movers()) {
    if (!names.empty()) names += ',';
    names += m.name();
  }
  s.set("movers", names);
  s.setBool("overlay", view_.overlaid);
  s.setBool("follow", follow_);
  s.setNumber("render-hz", view_.panels[0].renderHz);
  s.set("params.scene", scene_->name);
  for (std::size_t i = 0; i < params_.specs().size(); ++i)
    s.setNumber("param." + params_.specs()[i].name, params_.values()[i]);
  for (const ui::OverlayToggle& t : ui::overlayToggles()) {
    s.setBool(std::string("overlay.") + t.name, view_.panels[0].overlays.*t.flag);
  }
}

std::vector<MoverSpec> Debugger::movers() const {
  std::vector<MoverSpec> out;
  for (std::size_t k = 0; k < session_->size(); ++k) {
    const ui::Source& s = session_->panel(k);
    if (const ui::SimSource* sim = s.sim()) {
      out.push_back(sim->simulation().moverSpec());
    } else if (const ui::ReplaySource* r = s.replay(); r && r->recording().options().mover) {
      out.push_back(*r->recording().options().mover);
    }
  }
  return out;
}

bool Debugger::idle() const {
  return paused_ && !deferred_ && checks_.done() && (!showSweep_ || sweep_.pending() == 0);
}

// -- sources -------------------------------------------------------------------------------------

void Debugger::adopt(std::unique_ptr<ui::Session> session, bool keepCamera) {
  const ui::DebuggerState first = view_.panels.empty() ? ui::DebuggerState{} : view_.panels.front();
  session_ = std::move(session);
  view_.panels.assign(1, first);
  if (!keepCamera) {
    view_.panels[0].frameView = session_->primary().home();
    view_.panels[0].error.clear();
  }
  ui::syncPanels(view_, *session_);
  for (auto& st : view_.panels) {
    st.overlays = first.overlays;
    st.renderHz = first.renderHz;
    if (!keepCamera) st.frameView = view_.panels[0].frameView;
  }
  if (const ui::SimSource* sim = session_->primary().sim()) ui::syncDraft(view_.panels[0], *sim);
  view_.inspected = 0;
  checks_.reset(*session_, pinned_);
  clock_ = 0.0;
}

void Debugger::buildScene(const sim::SceneDef& scene, const sim::Params& params,
                          std::vector<MoverSpec> movers, std::uint64_t landOn, ui::SourceKind kind) {
  // Everything is built first, so a rejected combination changes nothing.
  std::vector<std::unique_ptr<ui::Source>> panels;
  const std::optional<std::size_t> body =
      session_ && session_->primary().sim() ? session_->primary().sim()->tracedBody() : std::nullopt;
  for (const MoverSpec& m : movers) {
    auto s = std::make_unique<ui::SimSource>(scene, params, m, kind);
    const sim::Simulation& sim = s->simulation();
    // A tick that would take seconds is refused here, before anything runs (and freezes).
    if (auto why = app::workLimitExceeded(params, sim.moverSpec(), sim.bodies().size()))
      throw Error(*why);
    const std::size_t n = sim.bodies().size();
    // The same body stays traced; a scene with fewer bodies traces its first.
    if (body) s->traceBody(*body < n ? *body : (n > 0 ? std::optional<std::size_t>(0) : std::nullopt));
    s->setRenderHz(view_.panels.empty() ? 0.0 : view_.panels[0].renderHz);
    if (!files_.empty() && kind == ui::SourceKind::level) s->setNotes(files_.back().notes());
    panels.push_back(std::move(s));
  }
  if (panels.empty()) fail("tv-debugger", "no mover to run");
  const bool sameScene = scene_ == &scene;
  auto session = std::make_unique<ui::Session>(std::move(panels));
  // How long a re-run to this tick takes decides whether sliders follow live.
  const auto t0 = std::chrono::steady_clock::now();
  session->goTo(landOn, true);
  const std::chrono::duration<double, std::milli> spent = std::chrono::steady_clock::now() - t0;
  scene_ = &scene;
  params_ = params;
  adopt(std::move(session), sameScene);
  view_.panels[0].lastRerunMs = spent.count();
}

void Debugger::loadScene(const sim::SceneDef& scene) {
  try {
    // A scene keeps the movers compared; from a recording (whose panels are what-ifs) it
    // starts with the exact sweep.
    std::vector<MoverSpec> m = isScene() ? movers() : std::vector<MoverSpec>{};
    if (m.empty()) m = {MoverSpec{.kind = MoverKind::continuous}};
    buildScene(scene, scene.defaults(), std::move(m), 0, ui::SourceKind::scene);
    if (session_->primary().sim()->tracedBody() == std::nullopt &&
        !session_->primary().sim()->simulation().bodies().empty())
      select(session_->primary().sim()->simulation().bodies()[0].item);
    message_.clear();
    notice_.clear();
  } catch (const Error& e) {
    reportError("scene '" + scene.name + "': " + app::userMessage(e));
  }
}

void Debugger::openFile(const std::string& path) {
  // A recording typed into the level picker (or dropped) opens as what it is.
  if (path.ends_with(".tvrec")) {
    tryOpenRecording(path);
    return;
  }
  const app::SceneSource file = app::SceneSource::forFile(path);
  try {
    const sim::SceneDef& scene = file.scene();  // throws naming the file, JSON path and value
    files_.push_back(file);
    std::vector<MoverSpec> m = isScene() ? movers() : std::vector<MoverSpec>{};
    if (const auto suggested = file.mover()) m = {*suggested};
    if (m.empty()) m = {MoverSpec{.kind = MoverKind::continuous}};
    buildScene(scene, scene.defaults(), std::move(m), 0, ui::SourceKind::level);
    message_.clear();
    // A file's notes are shown where the person looks, not only on stderr.
    for (const std::string& note : file.notes()) notice_ = note;
  } catch (const Error& e) {
    reportError(app::userMessage(e));
  }
}

void Debugger::openRecording(const std::string& path) {
  auto source = ui::ReplaySource::open(path);  // throws naming the file: nothing changed
  scene_ = nullptr;
  updatesAsMoves_ = false;
  paused_ = true;
  follow_ = false;
  ui::DebuggerState& first = view_.panels[0];
  first.overlays.positions = false;  // no render rate in a recording: the positions coincide
  adopt(std::make_unique<ui::Session>(std::move(source)), false);
  traceBusiest();
  frameAll();
  message_.clear();
  notice_.clear();
}

void Debugger::tryOpenRecording(const std::string& path) {
  try {
    openRecording(path);
  } catch (const std::exception& e) {
    reportError(app::userMessage(e));
  }
}

void Debugger::traceBusiest() {
  // Something to look at from the first frame: the item that moves most (the player, usually).
  const ui::ReplaySource* r = session_->primary().replay();
  if (!r) return;
  const RecordedItem* busiest = nullptr;
  for (const RecordedItem& i : r->recording().items()) {
    if (i.moves > 0 && (!busiest || i.moves > busiest->moves)) busiest = &i;
  }
  if (busiest) session_->trace(busiest->id);
}

void Debugger::show(std::uint64_t f, std::optional<std::uint32_t> k,
                    const std::optional<std::string>& item) {
  ui::RecordingFlags r;
  r.frame = f;
  r.call = k;
  r.item = item;
  ui::showRecorded(*session_, r);
  view_.revealCall = true;
}

namespace {
bool sameMover(const MoverSpec& a, const MoverSpec& b) {
  return a.name() == b.name() && a.maxStep == b.maxStep;
}
}  // namespace

void Debugger::compareWith(const std::vector<MoverSpec>& movers, bool updatesAsMoves) {
  try {
    if (isScene()) {
      // A mover beside itself shows nothing new and its failures would be listed twice.
      const MoverSpec shown = this->movers().front();
      for (std::size_t i = 0; i < movers.size(); ++i) {
        const bool twice = sameMover(movers[i], shown) ||
                           std::any_of(movers.begin(), movers.begin() + static_cast<std::ptrdiff_t>(i),
                                       [&](const MoverSpec& m) { return sameMover(m, movers[i]); });
        if (twice) fail("what-if", movers[i].name() + " is already shown: pick another mover");
      }
      std::vector<MoverSpec> all = {this->movers().front()};
      all.insert(all.end(), movers.begin(), movers.end());
      setMovers(std::move(all));
      return;
    }
    // A recording: the recorded run as it is (frame, call, traced item), and one what-if run
    // per mover beside it, each once.
    for (std::size_t i = 0; i < movers.size(); ++i) {
      for (std::size_t j = 0; j < i; ++j) {
        if (sameMover(movers[i], movers[j])) {
          fail("what-if", movers[i].name() + " is already shown: pick another mover");
        }
      }
    }
    std::vector<std::unique_ptr<ui::Source>> panels;
    const ui::ReplaySource& recorded = *session_->primary().replay();
    for (const MoverSpec& m : movers) panels.push_back(recorded.whatIf(m, updatesAsMoves));
    updatesAsMoves_ = updatesAsMoves;
    session_->compareWith(std::move(panels));
    ui::syncPanels(view_, *session_);
    for (auto& st : view_.panels) {
      st.overlays = view_.panels[0].overlays;
      st.frameView = view_.panels[0].frameView ? view_.panels[0].frameView
                                               : std::optional<Rect>(view_.panels[0].camera.view());
    }
    checks_.reset(*session_, pinned_);
    message_.clear();
  } catch (const std::exception& e) {
    reportError(app::userMessage(e));
  }
}

void Debugger::setMovers(std::vector<MoverSpec> movers) {
  if (movers.empty() || !scene_) return;
  try {
    buildScene(*scene_, params_, std::move(movers), currentTick(),
               session_->primary().kind());
  } catch (const Error& e) {
    reportError(app::userMessage(e));
  }
}

// -- a live game ---------------------------------------------------------------------------------

ui::LiveSource* Debugger::liveSource() {
  return session_ ? dynamic_cast<ui::LiveSource*>(&session_->primary()) : nullptr;
}
const ui::LiveSource* Debugger::liveSource() const {
  return session_ ? dynamic_cast<const ui::LiveSource*>(&session_->primary()) : nullptr;
}

bool Debugger::live() const {
  return liveSource() != nullptr;
}

void Debugger::listen(const std::string& address, std::uint64_t keepFrames,
                      std::uint64_t keepMegabytes) {
  LiveReceiverOptions o;
  o.address = address;
  o.keepFrames = keepFrames;
  o.keepBytes = keepMegabytes << 20;
  // Throws naming the address when it is malformed or in use: nothing has changed then.
  auto rx = std::make_shared<LiveReceiver>(o);
  listenAddress_ = rx->address();
  receiver_ = rx;
  scene_ = nullptr;
  follow_ = true;
  paused_ = false;  // following the newest frame
  view_.panels[0].overlays.positions = false;
  adopt(std::make_unique<ui::Session>(std::make_unique<ui::LiveSource>(rx)), false);
  message_.clear();
  notice_ = "listening on " + listenAddress_;
}

void Debugger::tryListen(const std::string& address) {
  try {
    listen(address);
  } catch (const std::exception& e) {
    reportError(app::userMessage(e));
  }
}

bool Debugger::saveStream(const std::string& path) {
  try {
    const ui::LiveSource* l = liveSource();
    if (!l) fail("tv-debugger", "no live game to save");
    l->save(path);
    notice_ = "saved the frames kept (" + std::to_string(l->firstFrame()) + ".." +
              std::to_string(l->lastFrame()) + ") to " + path;
    message_.clear();
    return true;
  } catch (const std::exception& e) {
    reportError("save: " + app::userMessage(e));
    return false;
  }
}

void Debugger::refreshLive() {
  ui::LiveSource* l = liveSource();
  if (!l) return;
  const std::uint64_t run = l->run();
  for (const std::string& news : l->refresh(!paused_ || jumpToNewest_)) notice_ = news;
  if (l->run() != run) {
    // A new run: a game connected (again). Its world is a new one: frame it, trace its busiest,
    // and follow it as it comes (a pause was the last game's: the new one is not held).
    playingBack_ = false;
    checks_.reset(*session_, false);
    traceBusiest();
    frameAll();
    follow_ = true;
    paused_ = false;
    jumpToNewest_ = false;
  }
  if (playingBack_) return;  // the person plays the kept frames: advance() moves through them
  if ((!paused_ || jumpToNewest_) && l->lastFrame() != currentTick()) {
    session_->goTo(l->lastFrame());
    jumpToNewest_ = jumpToNewest_ && currentTick() < l->lastFrame();
  }
  if (!paused_ && l->ended() && currentTick() >= l->lastFrame()) paused_ = true;
}

// -- time ----------------------------------------------------------------------------------------

void Debugger::goTo(std::uint64_t f, bool stopAtEnd) {
  notice_.clear();  // a notice tells of the frame it was given at ("the scene ended at tick 5")
  try {
    session_->goTo(f, stopAtEnd);
  } catch (const std::exception& e) {
    paused_ = true;
    reportError(app::userMessage(e));
  }
  clock_ = 0.0;
}

void Debugger::advance(double seconds) {
  // A live game goes at its own pace (refreshLive), unless what it sent is being played back.
  if (paused_ || (live() && !playingBack_)) return;
  clock_ += seconds * speed_;
  const double step = session_->playSeconds();
  int n = 0;
  while (clock_ >= step && n < kMaxFramesPerDraw) {
    try {
      session_->play();
    } catch (const std::exception& e) {
      paused_ = true;
      reportError(app::userMessage(e));
      return;
    }
    clock_ -= step;
    ++n;
  }
  if (n == kMaxFramesPerDraw) clock_ = 0.0;
  // Nothing more can happen: stop, so the interesting frames stay in reach.
  if ((session_->ended() || playingBack_) && session_->frame() >= session_->lastFrame()) {
    paused_ = true;
    notice_ = isScene()      ? "the scene ended at tick " + std::to_string(currentTick()) +
                                   " (Play runs it again)"
              : playingBack_ ? "the last frame the game sent (Play runs them again)"
                             : "the end of the recording (Play runs it again)";
  }
}

void Debugger::select(std::optional<ItemId> item) {
  try {
    // An item picked in the outliner that is not in the world now: go to where it is.
    if (item && !session_->primary().world().has(*item)) {
      for (const ui::ItemRow& r : session_->primary().items()) {
        if (r.id != *item) continue;
        paused_ = true;
        session_->goTo(std::clamp(session_->frame(), r.firstFrame, r.lastFrame));
      }
    }
    session_->trace(item);
  } catch (const std::exception& e) {
    reportError(app::userMessage(e));
  }
}

void Debugger::selectCall(std::optional<std::uint32_t> k) {
  try {
    paused_ = true;
    session_->selectCall(k);
    view_.revealCall = true;
    view_.showTab = ui::Tab::inspector;
  } catch (const std::exception& e) {
    reportError(app::userMessage(e));
  }
}

void Debugger::goToFailure(std::size_t index) {
  view_.failures = checks_.failures();
  if (index >= view_.failures.entries.size()) return;
  paused_ = true;
  notice_.clear();
  try {
    ui::goToFailure(*session_, view_, index);
  } catch (const std::exception& e) {
    reportError(app::userMessage(e));
  }
  clock_ = 0.0;
  // Followed from there.
  follow_ = true;
}

void Debugger::goToDifference() {
  const auto d = checks_.firstDifference();
  if (!d) return;
  paused_ = true;
  // A recording's what-if says which move ended elsewhere first: that call, that item.
  if (const auto& r = checks_.whatIf(); r && !r->differences.empty() && !isScene()) {
    const MoveDifference& first = r->differences.front();
    goTo(first.frame);
    select(first.item);
    selectCall(first.call);
  } else {
    goTo(*d);
    // A scene's: the first body whose place differs between the panels.
    const ui::SimSource* a = session_->primary().sim();
    for (std::size_t k = 1; a && k < session_->size(); ++k) {
      const ui::SimSource* b = session_->panel(k).sim();
      if (!b) continue;
      const auto x = a->simulation().bodies(), y = b->simulation().bodies();
      for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
        if (x[i].rect != y[i].rect) {
          select(x[i].item);
          k = session_->size();
          break;
        }
      }
    }
  }
  follow_ = true;
  const Rect r = session_->followView();
  for (auto& st : view_.panels) st.frameView = r;
}

std::optional<tv::Divergence> Debugger::divergence() const {
  std::optional<tv::Divergence> out;
  const auto earlier = [&](const tv::Divergence& d) {
    if (!out || d.frame < out->frame || (d.frame == out->frame && d.call < out->call)) out = d;
  };
  if (const ui::ValidationJob* v = checks_.validation(); v && v->done()) {
    if (const auto d = v->divergence()) earlier(*d);
  }
  if (const ui::ReplaySource* r = session_->primary().replay()) {
    if (const auto& d = r->pictureDivergence()) earlier(*d);
  }
  return out;
}

void Debugger::goToDivergence() {
  const auto d = divergence();
  if (!d) return;
  const ui::ReplaySource* r = session_->primary().replay();
  if (!r) return;
  paused_ = true;
  goTo(d->frame);
  if (const auto id = r->findLabel(d->item)) select(*id);
  selectCall(d->call);
  view_.showTab = ui::Tab::inspector;
  follow_ = true;
  const Rect view = session_->followView();
  for (auto& st : view_.panels) st.frameView = view;
}

void Debugger::frameAll() {
  follow_ = false;
  const Rect home = session_->primary().home();
  for (auto& st : view_.panels) st.frameView = home;
}

void Debugger::reportError(const std::string& what) {
  message_ = what;
  if (!view_.panels.empty()) view_.panels[0].error = what;
}

void Debugger::clearError() {
  if (!view_.panels.empty() && view_.panels[0].error == message_) view_.panels[0].error.clear();
  message_.clear();
}

// -- tuning --------------------------------------------------------------------------------------

void Debugger::applyActions(const ui::Actions& a) {
  if (a.togglePause) run(Command::pause);
  if (a.step) run(Command::stepForward);
  if (a.stepBack) run(Command::stepBack);
  if (a.inspect) view_.inspected = std::min(*a.inspect, session_->size() - 1);
  if (a.item) select(*a.item);
  if (a.call) selectCall(*a.call);
  if (a.failure) goToFailure(*a.failure);
  if (!(a.restart || a.apply) || !scene_) return;
  ui::DebuggerState& st = view_.panels[0];
  // The render rate applies at once, to every panel.
  for (std::size_t k = 0; k < session_->size(); ++k) {
    if (ui::SimSource* s = session_->panel(k).sim()) s->setRenderHz(st.renderHz);
  }
  if (st.draftScene != scene_->name) {
    if (const sim::SceneDef* s = sim::builtinScenes().tryFind(st.draftScene)) loadScene(*s);
    return;
  }
  // An edit lands on the tick on screen, however many edits a drag made before it (a release
  // after a live drag changes nothing more, and must not send the view to tick 0); Restart
  // goes to tick 0.
  restartFromDraft(!a.restart);
}

void Debugger::restartFromDraft(bool sameTick) {
  ui::DebuggerState& st = view_.panels[0];
  std::vector<MoverSpec> movers = this->movers();
  movers.front() = st.draftMover;
  for (std::size_t k = 1; k < movers.size(); ++k) {
    if (movers[k].name() == st.draftMover.name()) {
      reportError("mover: " + st.draftMover.name() + " is already compared (panel " +
                  std::to_string(k + 1) + ")");
      ui::syncDraft(st, *session_->primary().sim());
      st.error = message_;
      return;
    }
  }
  try {
    // A tune re-runs from tick 0 and lands on the same tick; a restart goes to tick 0. A tune
    // that shortens the scene lands on its new end, and says so.
    const std::uint64_t wanted = sameTick ? currentTick() : 0;
    buildScene(*scene_, st.draft, std::move(movers), wanted, session_->primary().kind());
    message_.clear();
    notice_.clear();
    if (currentTick() < wanted) {
      notice_ = "the scene now ends at tick " + std::to_string(currentTick()) + ", before tick " +
                std::to_string(wanted);
    }
  } catch (const Error& e) {
    // Refused: the panel shows the values that run, with the reason beside them.
    reportError(app::userMessage(e));
    ui::syncDraft(st, *session_->primary().sim());
    st.error = message_;
  }
}

void Debugger::applyOrDefer(const ui::Actions& a) {
  // A re-run known to be slow is shown as coming ("re-running...") and done on the next frame,
  // so the window says what it is doing before it is busy.
  if ((a.restart || a.apply) && view_.panels[0].lastRerunMs >= ui::kLiveRerunMs && !pinned_) {
    ui::Actions now = a;
    now.restart = now.apply = false;
    applyActions(now);
    deferred_ = true;
    deferredRestart_ = a.restart;
    notice_ = "re-running to tick " + std::to_string(currentTick()) + " (the last re-run took " +
              std::to_string(static_cast<int>(view_.panels[0].lastRerunMs)) + " ms)...";
    return;
  }
  applyActions(a);
}

bool Debugger::tune(const std::string& param, double value) {
  ui::DebuggerState& st = view_.panels[0];
  if (!scene_) {
    reportError("a recording has no parameters to tune");
    return false;
  }
  try {
    st.draft.set(param, value);
  } catch (const Error& e) {
    reportError(app::userMessage(e));
    return false;
  }
  message_.clear();
  ui::Actions a;
  a.apply = true;
  applyActions(a);
  return message_.empty();
}

MoverSpec Debugger::sweptMover() const {
  const std::vector<MoverSpec> m = movers();
  for (const MoverSpec& x : m) {
    if (x.kind == MoverKind::substep) return x;
  }
  return m.empty() ? MoverSpec{.kind = MoverKind::substep} : m.front();
}

void Debugger::useSubstepLength(double length) {
  if (!scene_) return;
  sim::Params p = params_;
  std::vector<MoverSpec> movers = this->movers();
  // The length applies to every substep mover through the parameter. With none, one mover
  // becomes substep-discrete (what the sweep ran); a comparison gains it as a new panel, so its
  // "before" stays.
  if (sweptMover().kind != MoverKind::substep) {
    if (session_->comparing()) {
      movers.push_back(MoverSpec{.kind = MoverKind::substep});
    } else {
      movers.front() = MoverSpec{.kind = MoverKind::substep};
    }
  }
  try {
    p.set(sim::param::substep, length);
    buildScene(*scene_, p, std::move(movers), currentTick(), session_->primary().kind());
    message_.clear();
  } catch (const Error& e) {
    reportError(app::userMessage(e));
  }
}

// -- commands ------------------------------------------------------------------------------------

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
      ui::LiveSource* l = liveSource();
      // With no game connected, what it sent plays back as a recording does (below).
      playingBack_ = l != nullptr && !l->connected();
      if (l != nullptr && l->connected()) {
        // Pause holds the game at its next frame, where it allows it; either way the view
        // stops following. Play lets it go on and follows the newest frame again.
        if (paused_) {
          if (l->controllable()) l->receiver().resume();
          paused_ = false;
        } else {
          if (l->controllable()) l->receiver().pause();
          paused_ = true;
          checks_.reset(*session_, pinned_);  // what is kept now, checked
        }
        break;
      }
      // Play at the end plays it again, and says so, rather than pausing at once.
      if (paused_ && (session_->ended() || playingBack_) &&
          session_->frame() >= session_->lastFrame()) {
        const std::uint64_t end = currentTick();
        goTo(session_->firstFrame());
        notice_ = std::string(isScene()      ? "the scene had ended at tick "
                              : playingBack_ ? "the game's frames end at frame "
                                             : "the recording ends at frame ") +
                  std::to_string(end) + ": playing again from " +
                  std::to_string(session_->firstFrame());
      }
      paused_ = !paused_;
      clock_ = 0.0;
      break;
    }
    case Command::step:
      paused_ = true;
      notice_.clear();
      if (ui::LiveSource* l = liveSource()) {
        // One more frame of the game, then held again; shown when it arrives. With no game
        // connected, the next of the frames it sent.
        playingBack_ = !l->connected();
        if (l->controllable() && l->connected()) {
          l->receiver().step();
          jumpToNewest_ = true;
        } else {
          goTo(currentTick() + 1);
        }
        break;
      }
      if (isScene()) {
        // One tick forward, kept in the history as it runs.
        for (std::size_t k = 0; k < session_->size(); ++k) session_->panel(k).sim()->tick();
      } else {
        goTo(currentTick() + 1);
      }
      break;
    case Command::stepBack:
      paused_ = true;
      if (currentTick() > session_->firstFrame()) goTo(currentTick() - 1);
      break;
    case Command::stepForward:
      paused_ = true;
      goTo(currentTick() + 1);
      break;
    case Command::nextCall:
      paused_ = true;
      session_->stepCall(+1);
      view_.revealCall = true;
      break;
    case Command::previousCall:
      paused_ = true;
      session_->stepCall(-1);
      view_.revealCall = true;
      break;
    case Command::frameEnd:
      selectCall(std::nullopt);
      break;
    case Command::restart:
      paused_ = true;
      if (scene_) {
        try {
          buildScene(*scene_, params_, movers(), 0, session_->primary().kind());
        } catch (const Error& e) {
          reportError(app::userMessage(e));
        }
      } else {
        goTo(session_->firstFrame());
      }
      break;
    case Command::slower:
      speed_ = std::max(kMinSpeed, speed_ * 0.5);
      break;
    case Command::faster:
      speed_ = std::min(kMaxSpeed, speed_ * 2.0);
      break;
    case Command::frameAll:
      frameAll();
      break;
    case Command::follow:
      follow_ = !follow_;
      if (!follow_) frameAll();
      break;
    case Command::compare:
      if (session_->comparing()) {
        compareWith({});
      } else if (isScene()) {
        setMovers(naivePatchExact());
      } else {
        compareWith({MoverSpec{.kind = MoverKind::discrete}});
      }
      break;
    case Command::overlay:
      // Only compared panels can be overlaid: flipping a setting nobody sees changed how the
      // next what-if opened.
      if (session_->comparing()) {
        view_.overlaid = !view_.overlaid;
        notice_.clear();  // a hint that compared movers were needed no longer holds
      } else {
        notice_ = "overlaid (V) is for compared movers: compare first (C, or W for a what-if)";
      }
      break;
    case Command::sweep:
      showSweep_ = isScene() && !showSweep_;
      break;
    case Command::whatIf:
      showWhatIf_ = !showWhatIf_;
      if (showWhatIf_) {
        // Offer a mover that is not shown yet (the dialog kept the last one picked, often the
        // mover on screen: run beside itself it shows nothing new).
        const std::vector<MoverSpec> shown = movers();
        const auto isShown = [&](const MoverSpec& m) {
          return std::any_of(shown.begin(), shown.end(),
                             [&](const MoverSpec& s) { return sameMover(s, m); });
        };
        if (isShown(draftWhatIf_)) {
          for (const MoverEntry& m : moverTable()) {
            if (!isShown(m.spec)) {
              draftWhatIf_ = m.spec;
              break;
            }
          }
        }
      }
      break;
    case Command::items:
      view_.showTab = ui::Tab::items;
      view_.items.focus = true;  // what is typed next goes into the search
      break;
    case Command::failures:
      view_.showTab = ui::Tab::failures;
      break;
    case Command::firstFailure:
      // The earliest, whichever panel it is in.
      if (const auto first = ui::firstFailureIndex(checks_.failures())) goToFailure(*first);
      break;
    case Command::openScene:
      openPicker_ = true;
      break;
    case Command::openRecording:
      recordingDialog_.open();
      break;
    case Command::previousScene:
      loadScene(all[(sceneIndex() + all.size() - 1) % all.size()]);
      break;
    case Command::nextScene:
      loadScene(all[(sceneIndex() + 1) % all.size()]);
      break;
    case Command::help:
      showHelp_ = !showHelp_;
      helpFollows_ = showHelp_;
      break;
    case Command::quit:
      quit_ = true;
      break;
  }
}

}  // namespace tv::viewer
