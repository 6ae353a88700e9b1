// The debugger's windows around the drawing layer's layouts: menus, the timeline, the scene
// picker, the comparison (side by side or overlaid), Help and the substep sweep; and the
// keyboard shortcuts.
//
// [SECTION] the frame
// [SECTION] keys
// [SECTION] menu bar
// [SECTION] timeline
// [SECTION] world: one mover, side by side, overlaid
// [SECTION] scene picker, substep sweep
#include <algorithm>
#include <cctype>
#include <cinttypes>
#include <cstdio>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "debugger.hpp"
#include "imgui.h"
#include "timeline.hpp"
#include "tv/app/user_message.hpp"
#include "tv/error.hpp"
#include "tv/ui/layout.hpp"
#include "tv/ui/palette.hpp"

namespace tv::viewer {

namespace pal = ui::palette;

namespace {

constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                    ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                    ImGuiWindowFlags_NoFocusOnAppearing;
constexpr double kSpeeds[] = {0.25, 0.5, 1.0, 2.0, 4.0};

ImVec4 colour(ImU32 c) {
  return ImGui::ColorConvertU32ToFloat4(c);
}

bool menuItem(const char* label, Command c, bool selected = false, bool enabled = true) {
  return ImGui::MenuItem(label, keysOf(c), selected, enabled);
}

}  // namespace

// [SECTION] the frame ------------------------------------------------------------------------

void Debugger::frame(double seconds, std::span<const KeyPress> keys) {
  if (recording_) {
    recording_->frame(seconds, keys);
    if (!recording_->wantsClose()) return;
    states_[0].overlays = recording_->overlays();
    recording_.reset();
    return;
  }
  // Smoothed over ~10 frames, so the readout is steady enough to read. A frame that waited for
  // input (idle, paused) measures the wait, not the work: left out.
  if (!waited_)
    frameMs_ = frameMs_ == 0.0 ? seconds * 1e3 : 0.9 * frameMs_ + 0.1 * seconds * 1e3;
  waited_ = idle();
  if (deferred_) {
    deferred_ = false;
    ui::Actions restart;
    restart.restart = true;
    applyActions(restart);
  }
  handleKeys(keys);
  advance(seconds);
  // Look ahead for where the movers part, a few milliseconds a frame; screenshots run it to
  // the end so the marks do not depend on how fast the machine is.
  divergence_.advance(pinned_ ? 1e9 : 3.0);
  if (showSweep_) {
    const MoverSpec& m = sweptMover();
    // The whole scene where the look-ahead found its end (bounded), else up to now.
    std::uint64_t horizon = std::max<std::uint64_t>(tick(), 1);
    if (divergence_.done())
      horizon = std::max(horizon, std::min<std::uint64_t>(divergence_.known(), 600));
    if (sweep_.stale(*scene_, params_, m, horizon)) sweep_.reset(*scene_, params_, m, horizon);
    do {
    } while (sweep_.advance() && pinned_);
  }

  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float top = drawMenuBar();
  const ImGuiStyle& style = ImGui::GetStyle();
  const float bottom =
      ImGui::GetFrameHeight() * 2.0f + style.ItemSpacing.y + style.WindowPadding.y * 2.0f;
  const ImVec2 origin{0.0f, top};
  const ImVec2 size{display.x, std::max(display.y - top - bottom, 100.0f)};
  drawMain(origin, size);
  // After the world and its panels, so a panel that runs long never hides the timeline.
  drawTimeline(display, bottom);
  if (showHelp_) {
    // The width of the column of controls (see drawCompareSideBySide and ui::debuggerLayout).
    const float side = compare() && !overlay_ ? std::clamp(display.x * 0.30f, 340.0f, 440.0f)
                                              : std::clamp(display.x * 0.35f, 340.0f, 480.0f);
    drawHelp(&showHelp_, {display.x - side, top}, {side, size.y});
  }
  if (showSweep_) drawSweep();
  drawPicker();
  if (const auto path = recordingDialog_.draw()) tryOpenRecording(*path);
}

// [SECTION] keys -----------------------------------------------------------------------------

void Debugger::handleKeys(std::span<const KeyPress> keys) {
  const ImGuiIO& io = ImGui::GetIO();
  // A text field being edited, or a modal picker, keeps the keys.
  if (io.WantCaptureKeyboard || io.WantTextInput) return;
  for (const KeyPress& k : keys) {
    if (k.mods & GLFW_MOD_CONTROL) {
      if (k.key == GLFW_KEY_O) run(Command::openScene);
      if (k.key == GLFW_KEY_Q) run(Command::quit);
    } else if (k.key == GLFW_KEY_HOME) {
      run(Command::frameAll);
    } else if (k.key == GLFW_KEY_F1) {
      run(Command::help);
    } else if (k.key == GLFW_KEY_ESCAPE) {
      // The topmost window closes (the scene picker closes itself).
      if (showHelp_) {
        showHelp_ = false;
      } else if (showSweep_) {
        showSweep_ = false;
      }
    }
  }
  if (io.KeyCtrl) return;
  // Printable shortcuts by the character typed, so they follow the keyboard layout.
  for (const ImWchar ch : io.InputQueueCharacters) {
    switch (std::tolower(static_cast<int>(ch))) {
      case 'p':
      case ' ':
        run(Command::pause);
        break;
      case 'o':
        run(Command::step);
        break;
      case ',':
        run(Command::stepBack);
        break;
      case '.':
        run(Command::stepForward);
        break;
      case 'r':
        run(Command::restart);
        break;
      case '-':
        run(Command::slower);
        break;
      case '=':
      case '+':
        run(Command::faster);
        break;
      case 'f':
        run(Command::follow);
        break;
      case 'c':
        run(Command::compare);
        break;
      case 'v':
        run(Command::overlay);
        break;
      case 't':
        run(Command::sweep);
        break;
      case '[':
        run(Command::previousScene);
        break;
      case ']':
        run(Command::nextScene);
        break;
      case '?':
        run(Command::help);
        break;
      default:
        break;
    }
  }
}

// [SECTION] menu bar -------------------------------------------------------------------------

float Debugger::drawMenuBar() {
  if (!ImGui::BeginMainMenuBar()) return 0.0f;
  std::optional<Command> chosen;
  const auto item = [&](const char* label, Command c, bool selected = false) {
    if (menuItem(label, c, selected)) chosen = c;
  };
  if (ImGui::BeginMenu("File")) {
    item("Open scene...", Command::openScene);
    if (ImGui::MenuItem("Open recording...")) recordingDialog_.open();
    if (ImGui::MenuItem("Open file...")) openPicker_ = focusPath_ = true;  // the picker's path field
    item("Restart", Command::restart);
    ImGui::Separator();
    item("Quit", Command::quit);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Scenes")) {
    std::vector<std::string> categories;
    for (const sim::SceneDef& s : sim::builtinScenes().all()) {
      if (std::find(categories.begin(), categories.end(), s.category) == categories.end())
        categories.push_back(s.category);
    }
    for (const std::string& cat : categories) {
      if (!ImGui::BeginMenu(cat.c_str())) continue;
      for (const sim::SceneDef& s : sim::builtinScenes().all()) {
        if (s.category != cat) continue;
        if (ImGui::MenuItem(s.name.c_str(), nullptr, &s == scene_)) loadScene(s);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", s.description.c_str());
      }
      ImGui::EndMenu();
    }
    ImGui::Separator();
    item("Previous scene", Command::previousScene);
    item("Next scene", Command::nextScene);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Movers")) {
    ImGui::TextColored(colour(pal::kDim), compare() ? "compared (lockstep):" : "mover:");
    for (const MoverEntry& entry : moverTable()) {
      const std::string n(entry.name);
      const auto at = std::find_if(movers_.begin(), movers_.end(),
                                   [&](const MoverSpec& m) { return m.name() == n; });
      const bool on = at != movers_.end();
      if (ImGui::MenuItem(n.c_str(), nullptr, on)) {
        std::vector<MoverSpec> next = movers_;
        if (!compare()) {
          next = {entry.spec};
        } else if (on && next.size() > 1) {
          next.erase(next.begin() + (at - movers_.begin()));
        } else if (!on) {
          next.push_back(entry.spec);
        }
        setMovers(std::move(next));
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(entry.description).c_str());
    }
    ImGui::Separator();
    item(compare() ? "One mover" : "Compare discrete / substep / continuous", Command::compare);
    if (menuItem("Overlaid in one view", Command::overlay, overlay_, compare()))
      chosen = Command::overlay;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Time")) {
    item(paused_ ? "Play" : "Pause", Command::pause);
    item("Single step", Command::step);
    item("Step back", Command::stepBack);
    item("Step forward", Command::stepForward);
    item("Restart", Command::restart);
    ImGui::Separator();
    for (const double s : kSpeeds) {
      char label[16];
      std::snprintf(label, sizeof label, "%gx", s);
      if (ImGui::MenuItem(label, nullptr, speed_ == s)) speed_ = s;
    }
    item("Slower", Command::slower);
    item("Faster", Command::faster);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    item("Frame everything", Command::frameAll);
    item("Follow the traced body", Command::follow, follow_);
    item("Substep sweep", Command::sweep, showSweep_);
    if (ImGui::BeginMenu("Overlays")) {
      for (const ui::OverlayToggle& t : ui::overlayToggles()) {
        ImGui::MenuItem(t.name, nullptr, &(states_[0].overlays.*t.flag));
      }
      ImGui::EndMenu();
    }
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    item("Shortcuts and mouse", Command::help, showHelp_);
    ImGui::EndMenu();
  }
  // How long a frame takes, at the right end: is a 10^4-item scene still at 60 fps? Never in a
  // screenshot (it reads the clock).
  if (!pinned_) {
    char text[48];
    if (idle()) {
      std::snprintf(text, sizeof text, "idle (paused)");
    } else {
      std::snprintf(text, sizeof text, "frame %.1f ms", frameMs_);
    }
    const float w = ImGui::CalcTextSize(text).x + 2.0f * ImGui::GetStyle().ItemSpacing.x;
    ImGui::SameLine(ImGui::GetWindowWidth() - w);
    ImGui::TextColored(colour(pal::kDim), "%s", text);
  }
  const float h = ImGui::GetWindowHeight();
  ImGui::EndMainMenuBar();
  if (chosen) run(*chosen);
  return h;
}

// [SECTION] timeline -------------------------------------------------------------------------

void Debugger::drawTimeline(ImVec2 display, float h) {
  ImGui::SetNextWindowPos({0.0f, display.y - h}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({display.x, h}, ImGuiCond_Always);
  if (!ImGui::Begin("Timeline", nullptr,
                    kFixed | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar)) {
    ImGui::End();
    return;
  }
  std::optional<Command> chosen;
  const auto button = [&](const char* label, Command c) {
    char text[48];
    std::snprintf(text, sizeof text, "%s (%s)", label, keysOf(c));
    if (ImGui::Button(text)) chosen = c;
    ImGui::SameLine();
  };
  button("Back", Command::stepBack);
  button(paused_ ? "Play" : "Pause", Command::pause);
  button("Step", Command::step);
  button("Forward", Command::stepForward);
  button("Restart", Command::restart);
  // The playback rate (not the bodies' --speed): a short list, labelled before the widget.
  ImGui::AlignTextToFramePadding();
  ImGui::TextColored(colour(pal::kDim), "playback");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::CalcTextSize("0.25x").x + ImGui::GetFrameHeight() * 1.6f);
  char rate[16];
  std::snprintf(rate, sizeof rate, "%gx", speed_);
  if (ImGui::BeginCombo("##playback", rate)) {
    for (const double s : kSpeeds) {
      std::snprintf(rate, sizeof rate, "%gx", s);
      if (ImGui::Selectable(rate, speed_ == s)) speed_ = s;
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  ImGui::TextColored(colour(pal::kDim), "|");
  ImGui::SameLine();
  const std::uint64_t last = std::max({furthest_, divergence_.known(), tick(), std::uint64_t{1}});
  ImGui::Text("tick %" PRIu64 " of %" PRIu64 "%s", tick(), last, divergence_.done() ? "" : "+");
  TimelineMarks marks;
  marks.known = divergence_.known();
  marks.failure = divergence_.firstFailure();
  marks.failureText = divergence_.failureText();
  if (compare()) marks.difference = divergence_.firstDifference();
  ImGui::SameLine();
  // Each note goes on the row whole, in its short form when the long one does not fit; the
  // full text is on hover.
  const float go = ImGui::CalcTextSize("go").x + ImGui::GetStyle().FramePadding.x * 2.0f +
                   ImGui::GetStyle().ItemSpacing.x * 2.0f;
  const auto note = [&](ImU32 c, const char* full, const char* brief, const char* hover) {
    const float room = ImGui::GetContentRegionAvail().x - go;
    const char* text = ImGui::CalcTextSize(full).x <= room ? full : brief;
    if (ImGui::CalcTextSize(text).x > room) return false;
    ImGui::TextColored(colour(c), "%s", text);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", hover);
    ImGui::SameLine();
    return true;
  };
  if (!message_.empty()) {
    const std::string full = "|  " + message_;
    (void)note(pal::kBad, full.c_str(), "|  refused: hover, or see the panel", message_.c_str());
  } else if (!notice_.empty()) {
    const std::string full = "|  " + notice_;
    (void)note(pal::kRender, full.c_str(), "|  ended", notice_.c_str());
  } else {
    if (marks.failure) {
      char full[200], brief[64];
      std::snprintf(full, sizeof full, "|  first failure: tick %" PRIu64 ", %s", *marks.failure,
                    marks.failureText.c_str());
      std::snprintf(brief, sizeof brief, "|  failure: tick %" PRIu64, *marks.failure);
      if (note(pal::kBad, full, brief, marks.failureText.c_str())) {
        if (ImGui::SmallButton("go##failure")) goTo(*marks.failure);
        ImGui::SameLine();
      }
    }
    if (marks.difference) {
      char full[96], brief[64];
      std::snprintf(full, sizeof full, "|  movers differ from tick %" PRIu64, *marks.difference);
      std::snprintf(brief, sizeof brief, "|  differ: %" PRIu64, *marks.difference);
      if (note(pal::kRender, full, brief, "the first tick whose state hashes differ")) {
        if (ImGui::SmallButton("go##difference")) goTo(*marks.difference);
        ImGui::SameLine();
      }
    }
    if (!marks.failure && divergence_.done()) {
      ImGui::TextColored(colour(pal::kGood), "|  no failure in %" PRIu64 " ticks", marks.known);
      ImGui::SameLine();
    }
  }
  ImGui::Dummy({0.0f, 0.0f});  // ends the row of buttons
  if (auto to = timelineBar("##timeline", tick(), last, marks, ImGui::GetContentRegionAvail().x)) {
    paused_ = true;
    if (*to != tick()) goTo(*to);
  }
  ImGui::End();
  if (chosen) run(*chosen);
}

// [SECTION] world: one mover, side by side, overlaid -----------------------------------------

void Debugger::drawMain(ImVec2 origin, ImVec2 size) {
  for (auto& st : states_) {
    st.paused = paused_;
    st.cameraMoved = false;
  }
  if (follow_) {
    const Rect r = followRect();
    for (auto& st : states_) st.frameView = r;
  }
  if (compare() && !overlay_) {
    drawCompareSideBySide(origin, size);
  } else {
    const ui::Actions a = ui::debuggerLayout(*sessions_.front(), states_[0], origin, size);
    if (compare()) drawOverlaid();
    // A zoom or pan ends following: the person took the camera.
    if (follow_ && !states_[0].frameView) follow_ = false;
    applyOrDefer(a);
  }
}

void Debugger::drawCompareSideBySide(ImVec2 origin, ImVec2 size) {
  const float side = std::clamp(size.x * 0.30f, 340.0f, 440.0f);
  for (std::size_t k = 1; k < states_.size(); ++k) states_[k].overlays = states_[0].overlays;
  std::vector<ui::Session*> raw;
  for (auto& s : sessions_) raw.push_back(s.get());
  char title[256];
  std::snprintf(title, sizeof title,
                "%s   tick %" PRIu64
                "   %s %.2gx   |   speed %g px/s, tile %g px, dt %.2f ms   |   "
                "traced: %s",
                scene_->name.c_str(), tick(), paused_ ? "paused" : "running", speed_,
                params_.get(sim::param::speed), params_.get(sim::param::tile),
                params_.get(sim::param::dt) * 1000.0,
                selected_ ? ("body " + std::to_string(*selected_)).c_str() : "none");
  // Legend columns of at least ~150 px keep its labels whole.
  const int columns = std::clamp(static_cast<int>((size.x - side) / 150.0f), 3, 8);
  const auto pick =
      ui::comparisonLayout(raw, states_, title, origin, {size.x - side, size.y}, columns);
  syncCameras();
  if (follow_ && !states_[0].frameView) follow_ = false;

  ImGui::SetNextWindowPos({origin.x + size.x - side, origin.y}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({side, 0}, ImGuiCond_Always);
  ui::Actions a;
  float y = 0.0f;
  if (ImGui::Begin("Scene and mover", nullptr, kFixed)) {
    ImGui::TextColored(colour(pal::kDim), "parameters apply to every compared mover");
    a = ui::controlsContents(*sessions_.front(), states_[0]);
    y = ImGui::GetWindowHeight();
  }
  ImGui::End();
  ImGui::SetNextWindowPos({origin.x + size.x - side, origin.y + y}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({side, std::max(size.y - y, 60.0f)}, ImGuiCond_Always);
  char name[96];
  std::snprintf(name, sizeof name, "Inspector: %s###Inspector", movers_[inspected_].name().c_str());
  if (ImGui::Begin(name, nullptr, kFixed)) ui::inspectorContents(*sessions_[inspected_]);
  ImGui::End();
  if (pick) {
    inspected_ = pick->panel;
    a.select = pick->body;
  }
  applyOrDefer(a);
}

void Debugger::syncCameras() {
  // The panels are the same size: a zoom or pan in one is applied to all, so the movers are
  // always compared over the same ground. The camera itself is copied (centre and scale; each
  // panel places it on its own screen rect): re-framing the view would fit it inside the
  // panel's safe area and zoom out a little on every frame of a drag.
  for (std::size_t k = 0; k < states_.size(); ++k) {
    if (!states_[k].cameraMoved) continue;
    const ui::Camera cam = states_[k].camera;
    for (auto& st : states_) {
      st.camera = cam;
      st.frameView.reset();
      st.cameraMoved = false;
    }
    return;
  }
}

void Debugger::drawOverlaid() {
  // Appends to the world view's window, so the other movers are drawn under the panels.
  ImGui::Begin("World");
  ImDrawList& dl = *ImGui::GetWindowDrawList();
  const ui::Camera& cam = states_[0].camera;
  dl.PushClipRect(cam.screenMin(), cam.screenMax(), true);
  for (std::size_t k = 1; k < sessions_.size(); ++k) {
    const ImU32 tint = pal::kCompareTints[(k - 1) % std::size(pal::kCompareTints)];
    const sim::Simulation& s = sessions_[k]->sim();
    for (const sim::Body& b : s.bodies()) {
      if (!cam.sees(b.rect)) continue;
      dl.AddRect(cam.toScreenMin(b.rect), cam.toScreenMax(b.rect), tint, 0.0f, 0, 1.5f);
    }
    const auto moves = sessions_[k]->moves();
    if (!moves.empty()) {
      const MoveTrace& m = moves.back().trace;
      const Rect end = m.start.at(m.final);
      dl.AddLine(cam.toScreen(m.start.center()), cam.toScreen(end.center()), tint, 2.0f);
    }
  }
  dl.PopClipRect();
  ImGui::End();

  // Which outline is which mover, under the HUD.
  ImGui::SetNextWindowBgAlpha(0.82f);
  ImGui::SetNextWindowPos({cam.screenMin().x + 8.0f, cam.screenMin().y + states_[0].coveredTop},
                          ImGuiCond_Always);
  if (ImGui::Begin("Overlaid", nullptr,
                   ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                       ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                       ImGuiWindowFlags_NoNav)) {
    ImGui::Text("%s: the usual colours", movers_[0].name().c_str());
    for (std::size_t k = 1; k < sessions_.size(); ++k) {
      const ImU32 tint = pal::kCompareTints[(k - 1) % std::size(pal::kCompareTints)];
      const sim::Counters& c = sessions_[k]->sim().counters();
      ImGui::TextColored(colour(tint), "%s: outlines and path   (tunnelled %" PRIu64 ")",
                         movers_[k].name().c_str(), c.tunnelled);
    }
  }
  ImGui::End();
}

// [SECTION] scene picker, substep sweep ------------------------------------------------------

void Debugger::drawPicker() {
  if (openPicker_) {
    ImGui::OpenPopup("Open scene");
    pickerFilter_.clear();
    openPicker_ = false;
  }
  ImGui::SetNextWindowSize({460, 0}, ImGuiCond_Always);
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, {0.5f, 0.5f});
  if (!ImGui::BeginPopupModal("Open scene", nullptr, ImGuiWindowFlags_NoSavedSettings)) return;
  if (ImGui::IsWindowAppearing() && !focusPath_) ImGui::SetKeyboardFocusHere();
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "%s", pickerFilter_.c_str());
  const bool enter =
      ImGui::InputTextWithHint("##filter", "type to filter, Enter opens the first", buffer,
                               sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue);
  pickerFilter_ = buffer;
  std::string lower = pickerFilter_;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const sim::SceneDef* first = nullptr;
  const sim::SceneDef* chosen = nullptr;
  for (const sim::SceneDef& s : sim::builtinScenes().all()) {
    std::string hay = s.category + " " + s.name + " " + s.description;
    std::transform(hay.begin(), hay.end(), hay.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (hay.find(lower) == std::string::npos) continue;
    if (!first) first = &s;
    char label[160];
    std::snprintf(label, sizeof label, "%-16s %-11s %s", s.name.c_str(), s.category.c_str(),
                  s.description.c_str());
    if (ImGui::Selectable(label, &s == first)) chosen = &s;
  }
  if (enter && first) chosen = first;
  // A level from a file: a Tiled map or a scene file (files can also be dropped on the window).
  ImGui::Separator();
  ImGui::TextUnformatted("or a file: a Tiled map (.tmj, .json) or a scene file");
  char path[1024];
  std::snprintf(path, sizeof path, "%s", pickerPath_.c_str());
  ImGui::SetNextItemWidth(-90.0f);
  if (ImGui::IsWindowAppearing() && focusPath_) {
    ImGui::SetKeyboardFocusHere();
    focusPath_ = false;
  }
  const bool openPath = ImGui::InputTextWithHint("##path", "levels/meadow.tmj", path, sizeof path,
                                                 ImGuiInputTextFlags_EnterReturnsTrue);
  pickerPath_ = path;
  ImGui::SameLine();
  const bool openClicked = ImGui::Button("Open file");
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) ImGui::CloseCurrentPopup();
  if ((openPath || openClicked) && !pickerPath_.empty()) {
    ImGui::CloseCurrentPopup();
    openFile(pickerPath_);
  } else if (chosen) {
    ImGui::CloseCurrentPopup();
    loadScene(*chosen);
  }
  ImGui::EndPopup();
}

const MoverSpec& Debugger::sweptMover() const {
  for (const MoverSpec& m : movers_) {
    if (m.kind == MoverKind::substep) return m;
  }
  return movers_.front();
}

void Debugger::drawSweep() {
  const MoverSpec& m = sweptMover();
  const auto at = std::find_if(movers_.begin(), movers_.end(),
                               [&](const MoverSpec& x) { return &x == &m; });
  const std::size_t k = static_cast<std::size_t>(at - movers_.begin());
  const double current = m.kind == MoverKind::substep ? sessions_[k]->sim().moverSpec().maxStep
                                                      : params_.get(sim::param::substep);
  if (const auto length = sweep_.draw(&showSweep_, current)) useSubstepLength(*length);
}

void Debugger::useSubstepLength(double length) {
  const MoverSpec& m = sweptMover();
  sim::Params p = params_;
  std::vector<MoverSpec> movers = movers_;
  // The length applies to every substep mover through the parameter. With none, one mover
  // becomes substep-discrete (what the sweep ran); a comparison gains it as a new panel, so
  // its "before" stays.
  if (m.kind != MoverKind::substep) {
    if (compare()) {
      movers.push_back(MoverSpec{.kind = MoverKind::substep});
    } else {
      movers.front() = MoverSpec{.kind = MoverKind::substep};
    }
  }
  try {
    p.set(sim::param::substep, length);
    build(*scene_, p, std::move(movers), tick());
    message_.clear();
  } catch (const Error& e) {
    reportError(app::userMessage(e));
  }
}

}  // namespace tv::viewer
