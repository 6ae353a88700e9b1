// The recording debugger's model: opening, time (frames and calls), selection, keys, what-if.
#include "recording_debugger.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "imgui.h"
#include "tv/app/user_message.hpp"
#include "tv/error.hpp"
#include "tv/ui/picture_options.hpp"
#include "tv/ui/recording_still.hpp"

namespace tv::viewer {

namespace {

constexpr double kMinSpeed = 0.25, kMaxSpeed = 4.0;
// Recordings carry no frame rate; they play at a game's usual 60 frames a second.
constexpr double kFrameSeconds = 1.0 / 60.0;
// A re-run body this far from where the recording goes on makes the game's next goals moot.
constexpr double kFarAway = 64.0;

}  // namespace

RecordingDebugger::RecordingDebugger(const std::string& path, const ui::Overlays& overlays,
                                     bool pinned)
    : path_(path),
      session_(std::make_unique<ui::RecordingSession>(ui::openRecording(path))),
      pinned_(pinned) {
  state_.view.overlays = overlays;
  state_.view.paused = true;
  traceBusiest();
  frameAll();
  validation_.start(path_, pinned_);
}

void RecordingDebugger::traceBusiest() {
  // Something to look at from the first frame: the item that moves most (the player, usually).
  const RecordedItem* busiest = nullptr;
  for (const RecordedItem& r : session_->replay().items()) {
    if (r.moves > 0 && (!busiest || r.moves > busiest->moves)) busiest = &r;
  }
  if (busiest) session_->select(busiest->id);
}

RecordingDebugger::~RecordingDebugger() = default;

void RecordingDebugger::reopen(const std::string& path) {
  try {
    auto next = std::make_unique<ui::RecordingSession>(ui::openRecording(path));
    path_ = path;
    session_ = std::move(next);
    whatIf_.reset();
    traceBusiest();
    paused_ = true;
    message_.clear();
    frameAll();
    validation_.start(path_, pinned_);
  } catch (const std::exception& e) {
    report(app::userMessage(e));
  }
}

void RecordingDebugger::show(std::uint64_t f, std::optional<std::uint32_t> k,
                             const std::optional<std::string>& item) {
  if (f > session_->lastFrame()) {
    throw ui::UsageError{"--frame " + std::to_string(f) + ": the recording has frames 0.." +
                         std::to_string(session_->lastFrame())};
  }
  goTo(f);
  if (item) {
    const auto id = session_->findLabel(*item);
    if (!id) throw ui::UsageError{"--item: no recorded item is labelled '" + *item + "'"};
    select(id);
  }
  if (k) {
    if (*k >= session_->calls().size()) {
      throw ui::UsageError{"--call " + std::to_string(*k) + ": frame " + std::to_string(f) +
                           " has " + std::to_string(session_->calls().size()) + " calls"};
    }
    selectCall(k);
  }
}

void RecordingDebugger::setView(const ui::PictureOptions& o) {
  switch (o.view) {
    case ui::ViewKind::scene:
      frameAll();
      break;
    case ui::ViewKind::follow:
      follow_ = true;
      break;
    case ui::ViewKind::rect:
      follow_ = false;
      state_.view.frameView = Rect{o.viewRect[0], o.viewRect[1], o.viewRect[2], o.viewRect[3]};
      break;
  }
}

bool RecordingDebugger::idle() const {
  return paused_ && !validation_.running() && !(whatIf_ && whatIf_->job.running());
}

void RecordingDebugger::report(const std::string& what) {
  message_ = what;
}

// -- time and selection ----------------------------------------------------------------------

void RecordingDebugger::goTo(std::uint64_t f) {
  try {
    session_->goTo(f);
    if (whatIf_) whatIf_->session->goTo(f);
    syncWhatIf();
  } catch (const std::exception& e) {
    paused_ = true;
    report(app::userMessage(e));
  }
}

void RecordingDebugger::selectCall(std::optional<std::uint32_t> k) {
  try {
    session_->selectCall(k);
    state_.revealCall = true;
    state_.showTab = 0;
    syncWhatIf();
  } catch (const std::exception& e) {
    report(app::userMessage(e));
  }
}

void RecordingDebugger::select(std::optional<ItemId> item) {
  try {
    // An item picked in the outliner that is not in the world now: go to where it is.
    if (item && !session_->world().has(*item)) {
      for (const RecordedItem& r : session_->replay().items()) {
        if (r.id != *item) continue;
        paused_ = true;
        session_->goTo(std::clamp(session_->frame(), r.firstFrame, r.lastFrame));
        if (whatIf_) whatIf_->session->goTo(session_->frame());
      }
    }
    session_->select(item);
    syncWhatIf();
  } catch (const std::exception& e) {
    report(app::userMessage(e));
  }
}

void RecordingDebugger::syncWhatIf() {
  if (!whatIf_) return;
  ui::RecordingSession& w = *whatIf_->session;
  if (w.frame() != session_->frame()) w.goTo(session_->frame());
  if (w.selected() != session_->selected()) w.select(session_->selected());
  if (w.call() != session_->call()) w.selectCall(session_->call());
}

void RecordingDebugger::stepCall(int direction) {
  paused_ = true;
  const std::size_t n = session_->calls().size();
  const auto current = session_->call();
  if (direction > 0) {
    if (!current && n > 0) return selectCall(0);
    if (current && *current + 1 < n) return selectCall(*current + 1);
    // Past the frame's last call: the next frame's first.
    if (session_->frame() < session_->lastFrame()) {
      goTo(session_->frame() + 1);
      if (!session_->calls().empty()) selectCall(0);
    }
    return;
  }
  if (current && *current > 0) return selectCall(*current - 1);
  if (current) return selectCall(std::nullopt);
  if (session_->frame() > 0) {
    goTo(session_->frame() - 1);
    const std::size_t m = session_->calls().size();
    if (m > 0) selectCall(static_cast<std::uint32_t>(m - 1));
  }
}

void RecordingDebugger::advance(double seconds) {
  if (paused_) return;
  clock_ += seconds * speed_;
  int n = 0;
  while (clock_ >= kFrameSeconds && n < 16) {
    clock_ -= kFrameSeconds;
    ++n;
  }
  if (n == 16) clock_ = 0.0;
  if (n == 0) return;
  const std::uint64_t to =
      std::min(session_->frame() + static_cast<std::uint64_t>(n), session_->lastFrame());
  goTo(to);
  if (to == session_->lastFrame()) paused_ = true;
}

void RecordingDebugger::frameAll() {
  follow_ = false;
  state_.view.frameView = session_->bounds();
  if (whatIf_) whatIf_->view.frameView = state_.view.frameView;
}

Rect RecordingDebugger::followRect() const {
  const double minSide = std::max(8.0 * session_->typicalSize(), 64.0);
  Rect r = session_->followView(minSide);
  if (whatIf_) r = unite(r, whatIf_->session->followView(minSide));
  return r;
}

void RecordingDebugger::apply(const ui::RecordingActions& a) {
  if (a.item) select(*a.item);
  if (a.call) {
    paused_ = true;
    selectCall(*a.call);
  }
}

void RecordingDebugger::startWhatIf(const MoverSpec& mover, bool updatesAsMoves) {
  try {
    ReplayOptions o;
    o.mover = mover;
    o.updatesAsMoves = updatesAsMoves;
    o.tolerant = true;
    auto w = std::make_unique<WhatIf>();
    w->mover = mover;
    w->updatesAsMoves = updatesAsMoves;
    w->session = std::make_unique<ui::RecordingSession>(Replay::open(path_, o),
                                                        session_->name() + " with " + mover.name());
    w->view.overlays = state_.view.overlays;
    w->view.frameView = state_.view.frameView ? state_.view.frameView : state_.view.camera.view();
    w->view.paused = paused_;
    whatIf_ = std::move(w);
    syncWhatIf();
    whatIf_->job.start(path_, o, kFarAway, pinned_);
    message_.clear();
  } catch (const std::exception& e) {
    whatIf_.reset();
    report(app::userMessage(e));
  }
}

// -- keys --------------------------------------------------------------------------------------

void RecordingDebugger::handleKeys(std::span<const KeyPress> keys) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureKeyboard || io.WantTextInput) return;
  for (const KeyPress& k : keys) {
    if (k.mods & GLFW_MOD_CONTROL) {
      if (k.key == GLFW_KEY_O) dialog_.open();
      if (k.key == GLFW_KEY_Q) quit_ = true;
      continue;
    }
    switch (k.key) {
      case GLFW_KEY_HOME:
        frameAll();
        break;
      case GLFW_KEY_F1:
        showHelp_ = !showHelp_;
        break;
      case GLFW_KEY_DOWN:
        stepCall(+1);
        break;
      case GLFW_KEY_UP:
        stepCall(-1);
        break;
      case GLFW_KEY_ESCAPE:
        selectCall(std::nullopt);
        break;
      default:
        break;
    }
  }
  if (io.KeyCtrl) return;
  for (const ImWchar ch : io.InputQueueCharacters) {
    switch (std::tolower(static_cast<int>(ch))) {
      case 'p':
      case ' ':
        paused_ = !paused_;
        clock_ = 0.0;
        if (!paused_ && session_->frame() == session_->lastFrame()) goTo(0);
        break;
      case 'o':
      case '.':
        paused_ = true;
        goTo(session_->frame() + 1);
        break;
      case ',':
        paused_ = true;
        if (session_->frame() > 0) goTo(session_->frame() - 1);
        break;
      case 'r':
        paused_ = true;
        goTo(0);
        break;
      case '-':
        speed_ = std::max(kMinSpeed, speed_ * 0.5);
        break;
      case '=':
      case '+':
        speed_ = std::min(kMaxSpeed, speed_ * 2.0);
        break;
      case 'f':
        follow_ = !follow_;
        if (!follow_) frameAll();
        break;
      case 'w':
        showWhatIf_ = !showWhatIf_;
        break;
      case 'i':
        state_.showTab = 1;
        break;
      case '?':
        showHelp_ = !showHelp_;
        break;
      default:
        break;
    }
  }
}

// -- the open dialog ---------------------------------------------------------------------------

std::optional<std::string> OpenRecordingDialog::draw() {
  if (open_) {
    ImGui::OpenPopup("Open recording");
    error_.clear();
    open_ = false;
  }
  ImGui::SetNextWindowSize({520, 0}, ImGuiCond_Always);
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, {0.5f, 0.5f});
  if (!ImGui::BeginPopupModal("Open recording", nullptr, ImGuiWindowFlags_NoSavedSettings))
    return std::nullopt;
  std::optional<std::string> chosen;
  ImGui::TextWrapped("A .tvrec file written by tv::Recorder (or drop one on the window).");
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
  char buffer[1024];
  std::snprintf(buffer, sizeof buffer, "%s", path_.c_str());
  ImGui::SetNextItemWidth(-80.0f);
  const bool enter = ImGui::InputTextWithHint("##path", "path/to/game.tvrec", buffer, sizeof buffer,
                                              ImGuiInputTextFlags_EnterReturnsTrue);
  path_ = buffer;
  ImGui::SameLine();
  if ((ImGui::Button("Open") || enter) && !path_.empty()) chosen = path_;
  // The recordings in the folder the path names (or the current one), to click.
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path folder = path_.empty() ? fs::path(".") : fs::path(path_);
  if (!fs::is_directory(folder, ec)) folder = folder.parent_path();
  if (folder.empty()) folder = ".";
  ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(IM_COL32(150, 155, 165, 255)),
                     "recordings in %s:", folder.string().c_str());
  ImGui::BeginChild("files", {0, 160}, true);
  int shown = 0;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end && shown < 200;
       it.increment(ec)) {
    if (it->path().extension() != ".tvrec") continue;
    ++shown;
    const std::string p = it->path().lexically_normal().string();
    if (ImGui::Selectable(p.c_str())) chosen = p;
  }
  if (shown == 0) ImGui::TextDisabled("(none)");
  ImGui::EndChild();
  if (!error_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.35f, 1.0f), "%s", error_.c_str());
  if (ImGui::Button("Cancel (Esc)") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))
    ImGui::CloseCurrentPopup();
  if (chosen) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
  return chosen;
}

}  // namespace tv::viewer
