// The debugger's windows around the view: the frame, keys, menu bar, timeline, pickers, the
// what-if dialog and the substep sweep — one of each, for every source.
//
// [SECTION] the frame
// [SECTION] keys
// [SECTION] menu bar
// [SECTION] timeline and status
// [SECTION] pickers and dialogs
#include <algorithm>
#include <cctype>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <filesystem>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "debugger.hpp"
#include "imgui.h"
#include "timeline.hpp"
#include "tv/app/user_message.hpp"
#include "tv/error.hpp"
#include "tv/ui/palette.hpp"
#include "tv/ui/replay_source.hpp"
#include "tv/ui/sim_source.hpp"
#include "tv/ui/words.hpp"
#include "tv/record/live.hpp"
#include "tv/ui/live_source.hpp"

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

// [SECTION] the frame ----------------------------------------------------------------------------

void Debugger::frame(double seconds, std::span<const KeyPress> keys) {
  // Smoothed over ~10 frames, so the readout is steady enough to read. A frame that waited for
  // input (idle, paused) measures the wait, not the work: left out.
  if (!waited_) frameMs_ = frameMs_ == 0.0 ? seconds * 1e3 : 0.9 * frameMs_ + 0.1 * seconds * 1e3;
  waited_ = idle();
  if (deferred_) {
    deferred_ = false;
    ui::Actions later;
    later.restart = deferredRestart_;
    later.apply = !deferredRestart_;
    applyActions(later);
  }
  handleKeys(keys);
  refreshLive();
  advance(seconds);
  // Look ahead for where the run fails, a few milliseconds a frame; screenshots ran it to the
  // end already (setPinned).
  checks_.advance(pinned_ ? 1e9 : 3.0);
  view_.failures = checks_.failures();
  if (showSweep_ && scene_) {
    const MoverSpec m = sweptMover();
    // The whole scene where the look-ahead found its end (bounded), else up to now.
    std::uint64_t horizon = std::max<std::uint64_t>(currentTick(), 1);
    if (checks_.done()) horizon = std::max(horizon, std::min<std::uint64_t>(checks_.known(), 600));
    if (sweep_.stale(*scene_, params_, m, horizon)) sweep_.reset(*scene_, params_, m, horizon);
    do {
    } while (sweep_.advance() && pinned_);
  }
  for (auto& st : view_.panels) {
    st.paused = paused_;
    st.cameraMoved = false;
  }
  if (follow_) {
    const Rect r = session_->followView();
    for (auto& st : view_.panels) st.frameView = r;
  }

  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float top = drawMenuBar();
  const ImGuiStyle& style = ImGui::GetStyle();
  // Three rows: the buttons, the bar, and what the checks found (never crowded out by the
  // buttons: a long first failure and "movers differ" both fit at 1024 px).
  const float bottom =
      ImGui::GetFrameHeight() * 3.0f + style.ItemSpacing.y * 2.0f + style.WindowPadding.y * 2.0f;
  const ImVec2 origin{0.0f, top};
  const ImVec2 size{display.x, std::max(display.y - top - bottom, 100.0f)};
  const ui::Actions a = ui::sessionView(*session_, view_, origin, size);
  syncCameras();
  // A zoom or pan ends following: the person took the camera.
  if (follow_ && !view_.panels[0].frameView) follow_ = false;
  applyOrDefer(a);
  // After the view, so a panel that runs long never hides the timeline.
  drawTimeline(display, bottom);
  if (showHelp_) {
    // Over the column's tabs: the world (the moment that matters) and the controls above them
    // stay in view; a person who wants it elsewhere drags it.
    helpFollows_ = drawHelp(&showHelp_, view_.tabsPos, view_.tabsSize, helpFollows_);
  }
  if (showSweep_ && scene_) drawSweep();
  if (showWhatIf_) drawWhatIfDialog();
  drawLiveDialogs();
  drawPicker();
  const std::optional<std::string> recording = recordingDialog_.draw();
  if (recordingDialog_.takeEdited()) clearError();  // before the open, whose error stays
  if (recording) tryOpenRecording(*recording);
}

void Debugger::syncCameras() {
  // The panels are the same size: a zoom or pan in one is applied to all, so the runs are
  // always compared over the same ground. The camera itself is copied (centre and scale; each
  // panel places it on its own screen rect): re-framing the view would fit it inside the
  // panel's safe area and zoom out a little on every frame of a drag.
  for (std::size_t k = 0; k < view_.panels.size(); ++k) {
    if (!view_.panels[k].cameraMoved) continue;
    const ui::Camera cam = view_.panels[k].camera;
    for (auto& st : view_.panels) {
      st.camera = cam;
      st.frameView.reset();
      st.cameraMoved = false;
    }
    return;
  }
}

// [SECTION] keys ---------------------------------------------------------------------------------

void Debugger::handleKeys(std::span<const KeyPress> keys) {
  const ImGuiIO& io = ImGui::GetIO();
  // A text field being edited, or a modal picker, keeps the keys (a space typed in a search
  // field is a space, not Play).
  if (io.WantCaptureKeyboard || io.WantTextInput || 
      ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel))
    return;
  for (const KeyPress& k : keys) {
    if (k.mods & GLFW_MOD_CONTROL) {
      if (k.key == GLFW_KEY_O) run(Command::openScene);
      if (k.key == GLFW_KEY_R) run(Command::openRecording);
      if (k.key == GLFW_KEY_Q) run(Command::quit);
      continue;
    }
    switch (k.key) {
      case GLFW_KEY_HOME:
        run(Command::frameAll);
        break;
      case GLFW_KEY_F1:
        run(Command::help);
        break;
      case GLFW_KEY_DOWN:
        run(Command::nextCall);
        break;
      case GLFW_KEY_UP:
        run(Command::previousCall);
        break;
      case GLFW_KEY_ENTER:
      case GLFW_KEY_KP_ENTER:
        run(Command::frameEnd);
        break;
      case GLFW_KEY_ESCAPE:
        // The topmost window closes (the pickers close themselves).
        if (showHelp_) {
          showHelp_ = false;
        } else if (showWhatIf_) {
          showWhatIf_ = false;
        } else if (showSweep_) {
          showSweep_ = false;
        } else if (session_->call()) {
          run(Command::frameEnd);
        }
        break;
      default:
        break;
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
      case 'w':
        run(Command::whatIf);
        break;
      case 't':
        run(Command::sweep);
        break;
      case 'i':
        run(Command::items);
        break;
      case 'x':
        run(Command::failures);
        break;
      case 'g':
        run(Command::firstFailure);
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

// [SECTION] menu bar -----------------------------------------------------------------------------

float Debugger::drawMenuBar() {
  if (!ImGui::BeginMainMenuBar()) return 0.0f;
  std::optional<Command> chosen;
  const auto item = [&](const char* label, Command c, bool selected = false, bool enabled = true) {
    if (menuItem(label, c, selected, enabled)) chosen = c;
  };
  const bool scene = isScene();
  if (ImGui::BeginMenu("File")) {
    item("Open scene or level...", Command::openScene);
    if (ImGui::MenuItem("Open level file (map, scene file)...")) openPicker_ = focusPath_ = true;
    item("Open recording...", Command::openRecording);
    if (ImGui::MenuItem("Listen for a game...")) openListen_ = true;
    if (ImGui::MenuItem("Save the stream...", nullptr, false, live())) openSave_ = true;
    if (!scene && ImGui::MenuItem("Validate again")) checks_.reset(*session_, pinned_);
    item(scene ? "Restart" : "First frame", Command::restart);
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
    // A scene's panels are its movers in lockstep; a recording's are what-if re-runs beside it.
    ImGui::TextColored(colour(pal::kDim), "%s",
                       scene ? (session_->comparing() ? "compared (lockstep):" : "mover:")
                             : "what-if runs beside the recording:");
    const std::vector<MoverSpec> now = movers();
    for (const MoverEntry& entry : moverTable()) {
      const std::string n(entry.name);
      const auto at = std::find_if(now.begin(), now.end(),
                                   [&](const MoverSpec& m) { return m.name() == n; });
      const bool on = at != now.end();
      if (ImGui::MenuItem(n.c_str(), nullptr, on)) {
        std::vector<MoverSpec> next = now;
        if (scene && !session_->comparing()) {
          next = {entry.spec};
        } else if (on) {
          next.erase(next.begin() + (at - now.begin()));
        } else {
          next.push_back(entry.spec);
        }
        if (scene) {
          setMovers(std::move(next));
        } else {
          compareWith(next, updatesAsMoves_);
        }
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(entry.description).c_str());
    }
    ImGui::Separator();
    item(session_->comparing() ? "One panel" : (scene ? "Compare discrete / substep / continuous"
                                                      : "What-if: discrete"),
         Command::compare);
    item("Overlaid in one view", Command::overlay, view_.overlaid, session_->comparing());
    item("What-if under another mover...", Command::whatIf, showWhatIf_);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Time")) {
    item(paused_ ? "Play" : "Pause", Command::pause);
    item("Single step", Command::step);
    item("Step back", Command::stepBack);
    item("Step forward", Command::stepForward);
    item("Next call", Command::nextCall);
    item("Previous call", Command::previousCall);
    item("End of frame", Command::frameEnd);
    item(scene ? "Restart" : "First frame", Command::restart);
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
    item("Follow the traced move", Command::follow, follow_);
    item("Failures", Command::failures);
    item("Go to the first failure", Command::firstFailure, false,
         !checks_.failures().entries.empty());
    item("Items (search)", Command::items);
    item("Substep sweep", Command::sweep, showSweep_, scene);
    if (ImGui::BeginMenu("Overlays")) {
      for (const ui::OverlayToggle& t : ui::overlayToggles()) {
        if (ImGui::MenuItem(t.name, nullptr, &(view_.panels[0].overlays.*t.flag))) {
          for (auto& st : view_.panels) st.overlays = view_.panels[0].overlays;
        }
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

// [SECTION] timeline and status ------------------------------------------------------------------

std::string Debugger::tracedOnlyWords(const tv::Divergence& d) const {
  // The validation found it only re-running the calls traced, as the debugger draws them: the
  // game's own calls replay bit for bit, so this is the debugger's replay at fault, not the file.
  const ui::ValidationJob* v = checks_.validation();
  if (!v || !v->done() || !v->divergedTracedOnly()) return {};
  const auto found = v->divergence();
  if (!found || found->frame != d.frame || found->call != d.call) return {};
  return " (only when re-run traced: untraced, every call replays bit for bit)";
}

std::vector<std::string> Debugger::status() const {
  std::vector<std::string> out;
  if (!message_.empty()) {
    out.push_back(message_);
    return out;
  }
  if (!notice_.empty()) out.push_back(notice_);
  // A replay that differs from its recording is said first, and then nothing says "valid".
  const std::optional<tv::Divergence> diverged = divergence();
  if (diverged) out.push_back("DIVERGED at " + ui::divergenceWords(*diverged) + tracedOnlyWords(*diverged));
  const char* unit = isScene() ? "tick" : "frame";
  if (const auto f = checks_.firstFailure()) {
    out.push_back("first failure: " + std::string(unit) + " " + std::to_string(*f) + ", " +
                  checks_.failureText());
  }
  if (const auto d = checks_.firstDifference(); d && session_->comparing()) {
    out.push_back(std::string(session_->whatIf() ? "runs differ from frame " : "movers differ from tick ") +
                  std::to_string(*d));
  }
  if (const ui::ValidationJob* v = checks_.validation()) {
    if (v->running()) {
      if (const auto t = v->tracedProgress()) {
        out.push_back("validating traced: frame " + std::to_string(*t));
      } else {
        out.push_back("validating: frame " + std::to_string(v->progress()));
      }
    } else if (!v->error().empty()) {
      out.push_back("not validated: " + v->error());
    } else if (v->done() && !v->divergence() && !diverged) {
      const ui::ReplaySource* r = session_->primary().replay();
      if (r && r->recording().summary().damagedAt) {
        out.push_back("the file is cut or damaged at byte " +
                      std::to_string(*r->recording().summary().damagedAt) + ": frames 0.." +
                      std::to_string(r->recording().summary().frames - 1) + " checked, and they match");
      } else {
        out.push_back("valid: the replay matches the recording");
      }
    }
  }
  if (!checks_.firstFailure() && checks_.done() && isScene()) {
    out.push_back(noFailureWords());
  }
  return out;
}

std::string Debugger::noFailureWords() const {
  const std::size_t listed = checks_.failures().entries.size();
  if (listed == 0) return "no failure in " + std::to_string(checks_.known()) + " ticks";
  return "no mover fails more than another, but " + std::to_string(listed) +
         " failures are listed (Failures tab)";
}

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
  const bool scene = isScene();
  button("Back", Command::stepBack);
  const ui::LiveSource* game = liveSource();
  if (game != nullptr && game->connected()) {
    // A game that allows it is held and stepped from here; any game is followed or not. (Once
    // it has left, its frames play back as a recording's.)
    if (game->controllable()) {
      button(paused_ ? "Resume game" : "Pause game", Command::pause);
      button("Step game", Command::step);
    } else {
      button(paused_ ? "Follow" : "Stop following", Command::pause);
    }
  } else {
    button(paused_ ? "Play" : "Pause", Command::pause);
  }
  button("Forward", Command::stepForward);
  // Calls only where a frame has them to step through.
  if (!session_->calls().empty() || !scene) {
    button("Call", Command::previousCall);
    button("Call", Command::nextCall);
  }
  button(scene ? "Restart" : "First", Command::restart);
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
  const std::uint64_t first = session_->firstFrame();
  const std::uint64_t last =
      std::max({session_->lastFrame(), checks_.known(), currentTick(), first + 1});
  const char* unit = scene ? "tick" : "frame";
  ImGui::Text("%s %" PRIu64 " of %" PRIu64 "%s", unit, currentTick(), last,
              checks_.done() || !scene ? "" : "+");

  TimelineMarks marks;
  marks.unit = unit;
  marks.first = first;
  marks.known = checks_.known();
  marks.failure = checks_.firstFailure();
  marks.failureText = checks_.failureText();
  if (session_->comparing()) marks.difference = checks_.firstDifference();
  if (checks_.whatIf()) marks.implausible = checks_.whatIf()->firstImplausibleFrame;
  const std::optional<tv::Divergence> diverged = divergence();
  if (diverged) {
    marks.diverged = diverged->frame;
    marks.divergedText = ui::divergenceWords(*diverged) + tracedOnlyWords(*diverged);
  }
  for (const auto& e : checks_.failures().entries) {
    if (marks.failures.empty() || marks.failures.back() != e.failure.frame)
      marks.failures.push_back(e.failure.frame);
  }
  ImGui::Dummy({0.0f, 0.0f});  // ends the row of buttons
  if (auto to = timelineBar("##timeline", currentTick(), last, marks, ImGui::GetContentRegionAvail().x)) {
    paused_ = true;
    if (*to != currentTick()) goTo(*to);
  }
  // The status row. Each note goes on the row whole, in its short form when the long one does
  // not fit; the full text is on hover. What does not fit at all moves to the row's tooltip,
  // never dropped without a trace: the row says how many more there are.
  const float go = ImGui::CalcTextSize("go").x + ImGui::GetStyle().FramePadding.x * 2.0f +
                   ImGui::GetStyle().ItemSpacing.x * 2.0f;
  std::vector<std::string> dropped;
  bool firstNote = true;
  const auto note = [&](ImU32 c, const std::string& full, const std::string& brief,
                        const std::string& hover, bool withGo) {
    const float more = ImGui::CalcTextSize("  (+9 more)").x;
    const float bar = firstNote ? 0.0f : ImGui::CalcTextSize("|").x + ImGui::GetStyle().ItemSpacing.x;
    const float room = ImGui::GetContentRegionAvail().x - (withGo ? go : 0.0f) - more - bar;
    const std::string& text = ImGui::CalcTextSize(full.c_str()).x <= room ? full : brief;
    if (ImGui::CalcTextSize(text.c_str()).x > room) {
      dropped.push_back(hover);
      return false;
    }
    if (!firstNote) {
      ImGui::TextColored(colour(pal::kDim), "|");
      ImGui::SameLine();
    }
    ImGui::TextColored(colour(c), "%s", text.c_str());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", hover.c_str());
    ImGui::SameLine();
    firstNote = false;
    return true;
  };
  if (!message_.empty()) {
    (void)note(pal::kBad, message_, "refused: hover, or see the panel", message_, false);
  } else {
    if (const ui::LiveSource* l = liveSource()) {
      std::string state;
      if (l->run() == 0) {
        state = "live: waiting for a game at " + listenAddress_;
      } else if (l->ended()) {
        state = "live: the game left (run " + std::to_string(l->run()) + ")";
      } else {
        state = std::string("live: ") + (paused_ ? (l->controllable() ? "game held" : "not following")
                                                  : "following the newest frame");
      }
      (void)note(l->ended() || l->run() == 0 ? pal::kDim : pal::kGood, state, "live", state, false);
      if (l->dropped() > 0) {
        const std::string d = "dropped the oldest " + std::to_string(l->dropped()) + " frames";
        (void)note(pal::kRender, d, "dropped: hover", l->notes().back(), false);
      }
    }
    if (!notice_.empty()) (void)note(pal::kRender, notice_, "note: hover", notice_, false);
    if (marks.diverged) {
      const std::string full = "DIVERGED at " + marks.divergedText;
      const std::string brief = "DIVERGED: frame " + std::to_string(*marks.diverged);
      if (note(pal::kBad, full, brief, full, true)) {
        if (ImGui::SmallButton("go##diverged")) goToDivergence();
        ImGui::SameLine();
      }
    }
    if (marks.failure) {
      const std::string full = std::string("first failure: ") + unit + " " +
                               std::to_string(*marks.failure) + ", " + marks.failureText;
      const std::string brief = std::string("failure: ") + unit + " " + std::to_string(*marks.failure);
      if (note(pal::kBad, full, brief, marks.failureText, true)) {
        if (ImGui::SmallButton("go##failure")) chosen = Command::firstFailure;
        ImGui::SameLine();
      }
    }
    if (marks.difference) {
      const std::string full = std::string(session_->whatIf() ? "runs differ from frame "
                                                              : "movers differ from tick ") +
                               std::to_string(*marks.difference);
      const std::string brief = "differ: " + std::to_string(*marks.difference);
      if (note(pal::kRender, full, brief,
               "the first " + std::string(unit) + " where the panels' runs differ", true)) {
        if (ImGui::SmallButton("go##difference")) goToDifference();
        ImGui::SameLine();
      }
    }
    if (const ui::ValidationJob* v = checks_.validation()) {
      if (v->running()) {
        char text[96];
        if (const auto t = v->tracedProgress()) {
          std::snprintf(text, sizeof text, "validating traced: frame %" PRIu64, *t);
        } else {
          std::snprintf(text, sizeof text, "validating: frame %" PRIu64, v->progress());
        }
        (void)note(pal::kDim, text, "validating", text, false);
      } else if (!v->error().empty()) {
        (void)note(pal::kBad, "not validated: " + v->error(), "not validated", v->error(), false);
      } else if (v->done() && !v->divergence() && !marks.diverged) {
        const ui::ReplaySource* r = session_->primary().replay();
        if (r && r->recording().summary().damagedAt) {
          const std::string text = "the file is cut or damaged at byte " +
                                   std::to_string(*r->recording().summary().damagedAt) +
                                   ": only the frames before it were checked, and they match";
          (void)note(pal::kBad, text, "damaged file: hover", text, false);
        } else {
          (void)note(pal::kGood, "valid: the replay matches the recording", "valid",
                     "the replay matches the recording bit for bit", false);
        }
      }
    }
    if (!marks.failure && checks_.done() && scene) {
      // Failures listed that no mover has more of than another are not "no failure".
      const std::string text = noFailureWords();
      const bool none = checks_.failures().entries.empty();
      (void)note(none ? pal::kGood : pal::kBad, text, none ? "no failure" : "fail alike", text, false);
    }
    if (!dropped.empty()) {
      ImGui::TextColored(colour(pal::kDim), "  (+%zu more)", dropped.size());
      if (ImGui::IsItemHovered()) {
        std::string all;
        for (const std::string& d : dropped) all += (all.empty() ? "" : "\n") + d;
        ImGui::SetTooltip("%s", all.c_str());
      }
      ImGui::SameLine();
    }
  }
  ImGui::Dummy({0.0f, 0.0f});  // ends the status row
  ImGui::End();
  if (chosen) run(*chosen);
}

// [SECTION] pickers and dialogs ------------------------------------------------------------------

void Debugger::drawPicker() {
  if (openPicker_) {
    ImGui::OpenPopup("Open scene or level");
    pickerFilter_.clear();
    openPicker_ = false;
  }
  const float width = std::min(ImGui::GetIO().DisplaySize.x - 40.0f, 640.0f);
  ImGui::SetNextWindowSize({width, 0}, ImGuiCond_Always);
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, {0.5f, 0.5f});
  if (!ImGui::BeginPopupModal("Open scene or level", nullptr, ImGuiWindowFlags_NoSavedSettings))
    return;
  if (ImGui::IsWindowAppearing() && !focusPath_) ImGui::SetKeyboardFocusHere();
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "%s", pickerFilter_.c_str());
  ImGui::SetNextItemWidth(-1.0f);
  const bool enter = ImGui::InputTextWithHint("##filter", "type to filter, Enter opens the first",
                                              buffer, sizeof buffer,
                                              ImGuiInputTextFlags_EnterReturnsTrue);
  pickerFilter_ = buffer;
  std::string lower = pickerFilter_;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const sim::SceneDef* first = nullptr;
  const sim::SceneDef* chosen = nullptr;
  // Name and category in columns, the description beside them wrapped: never cut.
  if (ImGui::BeginTable("scenes", 3, ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg)) {
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed,
                            ImGui::CalcTextSize("bullets-enemies  ").x);
    ImGui::TableSetupColumn("category", ImGuiTableColumnFlags_WidthFixed,
                            ImGui::CalcTextSize("Tunnelling  ").x);
    ImGui::TableSetupColumn("what", ImGuiTableColumnFlags_WidthStretch);
    for (const sim::SceneDef& s : sim::builtinScenes().all()) {
      std::string hay = s.category + " " + s.name + " " + s.description;
      std::transform(hay.begin(), hay.end(), hay.begin(),
                     [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      if (hay.find(lower) == std::string::npos) continue;
      if (!first) first = &s;
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      if (ImGui::Selectable(s.name.c_str(), &s == first, ImGuiSelectableFlags_SpanAllColumns))
        chosen = &s;
      ImGui::TableNextColumn();
      ImGui::TextColored(colour(pal::kDim), "%s", s.category.c_str());
      ImGui::TableNextColumn();
      ImGui::TextWrapped("%s", s.description.c_str());
    }
    ImGui::EndTable();
  }
  if (enter && first) chosen = first;
  // A level from a file: a Tiled map or a scene file (files can also be dropped on the window).
  ImGui::Separator();
  ImGui::TextWrapped("or a level file: a Tiled map (.tmj, .json) or a scene file");
  char path[1024];
  std::snprintf(path, sizeof path, "%s", pickerPath_.c_str());
  ImGui::SetNextItemWidth(-ImGui::CalcTextSize("Open file").x - ImGui::GetStyle().FramePadding.x * 4.0f);
  if (ImGui::IsWindowAppearing() && focusPath_) {
    ImGui::SetKeyboardFocusHere();
    focusPath_ = false;
  }
  // As in Open recording: the last path, selected, is replaced by what is typed.
  const bool openPath = ImGui::InputTextWithHint(
      "##path", "levels/meadow.tmj", path, sizeof path,
      ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
  if (ImGui::IsItemEdited()) clearError();  // the error was about the path being changed
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

void Debugger::drawSweep() {
  const MoverSpec m = sweptMover();
  // The length the scene runs with: the parameter, or when it is 0 what that comes to (tile/2).
  const double param = params_.get(sim::param::substep);
  double current = param;
  for (std::size_t k = 0; k < session_->size(); ++k) {
    const ui::SimSource* s = session_->panel(k).sim();
    if (s && m.kind == MoverKind::substep && s->simulation().moverSpec().name() == m.name())
      current = s->simulation().moverSpec().maxStep;
  }
  if (current == 0.0) current = params_.get(sim::param::tile) * 0.5;
  if (const auto length = sweep_.draw(&showSweep_, current, param == 0.0)) useSubstepLength(*length);
}

void Debugger::drawWhatIfDialog() {
  ImGui::SetNextWindowSize({440, 0}, ImGuiCond_Always);
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, {0.5f, 0.5f});
  ImGui::SetNextWindowBgAlpha(1.0f);  // over the panels: their labels must not show through
  if (!ImGui::Begin("What-if: re-run under another mover (W)", &showWhatIf_,
                    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  const bool scene = isScene();
  ImGui::TextWrapped("%s", scene ? "The scene run again by another mover, in lockstep beside this "
                                   "one (its rules react to what the new mover does)."
                                 : "Every recorded move made again by another mover, beside the "
                                   "recorded run.");
  ImGui::SetNextItemWidth(220.0f);
  if (ImGui::BeginCombo("mover", draftWhatIf_.name().c_str())) {
    for (const MoverEntry& m : moverTable()) {
      const std::string name(m.name);
      if (ImGui::Selectable(name.c_str(), name == draftWhatIf_.name())) draftWhatIf_ = m.spec;
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(m.description).c_str());
    }
    ImGui::EndCombo();
  }
  const bool substep = draftWhatIf_.kind == MoverKind::substep;
  ImGui::BeginDisabled(!substep || scene);
  ImGui::SetNextItemWidth(220.0f);
  // A field one clicks and types into (a drag field wants a double click first); 0 is the
  // mover's default, said beside it.
  ImGui::InputDouble("substep length", &draftSubstep_, 0.0, 0.0, "%.6g");
  const bool lengthOk = !substep || scene || (draftSubstep_ >= 0.0 && draftSubstep_ <= 1e6);
  if (scene && substep) {
    // Greyed out in a scene: its substep length is the scene's own parameter.
    ImGui::TextDisabled("a scene's substep length is its 'substep' parameter (the panel)");
  }
  if (!lengthOk) {
    ImGui::TextColored(colour(pal::kBad), "substep length %g refused: 0 to 1e6", draftSubstep_);
  } else if (!scene && draftSubstep_ == 0.0) {
    ImGui::TextDisabled("0: half the smallest item");
  }
  ImGui::EndDisabled();
  if (!scene) {
    ImGui::Checkbox("treat a body's updates as moves", &draftUpdates_);
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip(
          "for games that move bodies themselves (x += v*dt, update, push out):\n"
          "each update that only changes a position is re-run as a move");
    }
  }
  ImGui::BeginDisabled(!lengthOk);
  const bool run = ImGui::Button("Run beside it");
  ImGui::EndDisabled();
  if (run) {
    MoverSpec m = draftWhatIf_;
    if (substep && !scene) m.maxStep = draftSubstep_;
    std::vector<MoverSpec> next = movers();
    if (scene) next.erase(next.begin());  // the first panel is the scene's own
    next.push_back(m);
    compareWith(next, draftUpdates_);
    // Done: the run shows beside this one, its report in the Failures tab; the dialog would
    // only cover the world.
    showWhatIf_ = false;
  }
  // Taking the re-runs away is offered only when there are some (a button that did nothing
  // read as "re-run only under this mover").
  if (session_->comparing()) {
    ImGui::SameLine();
    if (ImGui::Button("Close the re-runs")) {
      compareWith({});
      showWhatIf_ = false;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("show this run alone again");
  }
  if (!scene) {
    ImGui::PushStyleColor(ImGuiCol_Text, pal::kDim);
    ImGui::TextWrapped(
        "Open-loop: the game's recorded goals are replayed as they were; how the game would have "
        "reacted to a different outcome is not in the file.");
    ImGui::PopStyleColor();
    if (const auto& r = checks_.whatIf()) {
      ImGui::Text("%" PRIu64 " moves re-run; %zu ended elsewhere, %" PRIu64 " tunnelled", r->moves,
                  r->differences.size(), r->tunnelled);
    }
    if (!checks_.error().empty()) ImGui::TextColored(colour(pal::kBad), "%s", checks_.error().c_str());
  }
  ImGui::End();
}

void Debugger::drawLiveDialogs() {
  // Two small popups: where to listen, and where to save what a live game sent.
  const auto pathPopup = [&](const char* title, bool& opening, std::string& text, const char* hint,
                             const char* help, const char* action) -> bool {
    if (opening) {
      ImGui::OpenPopup(title);
      opening = false;
    }
    ImGui::SetNextWindowSize({460, 0}, ImGuiCond_Always);
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, {0.5f, 0.5f});
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_NoSavedSettings)) return false;
    ImGui::TextWrapped("%s", help);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, "%s", text.c_str());
    ImGui::SetNextItemWidth(-90.0f);
    const bool enter = ImGui::InputTextWithHint(
        "##text", hint, buffer, sizeof buffer,
        ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
    if (ImGui::IsItemEdited()) clearError();
    text = buffer;
    ImGui::SameLine();
    const bool go = (ImGui::Button(action) || enter) && !text.empty();
    if (go || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return go;
  };
  if (pathPopup("Listen for a game", openListen_, listenAddress_, "127.0.0.1:7720",
                "Where the debugger waits for a game streaming live: [HOST:]PORT (127.0.0.1 "
                "unless a host is given). Run the game with --live and this address (or TV_LIVE=address, "
                "where the game reads it: tv::liveFromEnvironment).",
                "Listen"))
    tryListen(listenAddress_);
  if (pathPopup("Save the stream", openSave_, savePath_, "live.tvrec",
                "The frames kept of the live game, written as a recording (.tvrec) that tv-replay "
                "validates and the debugger opens.",
                "Save"))
    (void)saveStream(savePath_);
}

std::optional<std::string> OpenRecordingDialog::draw() {
  if (open_) {
    ImGui::OpenPopup("Open recording");
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
  // The path last tried is there, selected: what is typed replaces it (it was appended to, so a
  // path typed after a failed "/tmp" became "/tmp/tmp/...").
  const bool enter = ImGui::InputTextWithHint(
      "##path", "path/to/game.tvrec", buffer, sizeof buffer,
      ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
  if (ImGui::IsItemEdited()) edited_ = true;
  path_ = buffer;
  ImGui::SameLine();
  if ((ImGui::Button("Open") || enter) && !path_.empty()) chosen = path_;
  // The recordings in the folder the path names (or the current one), to click.
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path folder = path_.empty() ? fs::path(".") : fs::path(path_);
  if (!fs::is_directory(folder, ec)) folder = folder.parent_path();
  if (folder.empty()) folder = ".";
  ImGui::TextColored(colour(pal::kDim), "recordings in %s:", folder.string().c_str());
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
  if (ImGui::Button("Cancel (Esc)") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))
    ImGui::CloseCurrentPopup();
  if (chosen) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
  return chosen;
}

}  // namespace tv::viewer
