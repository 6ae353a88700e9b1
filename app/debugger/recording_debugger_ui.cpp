// The recording debugger's windows: the frame, menu bar, timeline, the what-if comparison and
// its controls, and Help.
//
// [SECTION] the frame
// [SECTION] menu bar
// [SECTION] timeline
// [SECTION] what-if
// [SECTION] help
#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>

#include "imgui.h"
#include "recording_debugger.hpp"
#include "timeline.hpp"
#include "tv/app/user_message.hpp"
#include "tv/ui/palette.hpp"
#include "tv/ui/what_if_view.hpp"

namespace tv::viewer {

namespace pal = ui::palette;

namespace {

constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                    ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                    ImGuiWindowFlags_NoFocusOnAppearing;

ImVec4 colour(ImU32 c) {
  return ImGui::ColorConvertU32ToFloat4(c);
}

}  // namespace

// [SECTION] the frame ------------------------------------------------------------------------

void RecordingDebugger::frame(double seconds, std::span<const KeyPress> keys) {
  handleKeys(keys);
  advance(seconds);
  state_.view.paused = paused_;
  if (follow_) {
    const Rect r = followRect();
    state_.view.frameView = r;
    if (whatIf_) whatIf_->view.frameView = r;
  }
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float top = drawMenuBar();
  const ImGuiStyle& style = ImGui::GetStyle();
  const float bottom =
      ImGui::GetFrameHeight() * 2.0f + style.ItemSpacing.y + style.WindowPadding.y * 2.0f;
  const ImVec2 origin{0.0f, top};
  const ImVec2 size{display.x, std::max(display.y - top - bottom, 100.0f)};
  if (whatIf_) {
    drawWhatIfSideBySide(origin, size);
  } else {
    const ui::RecordingActions a = ui::recordingLayout(*session_, state_, origin, size);
    if (follow_ && !state_.view.frameView) follow_ = false;  // a zoom or pan took the camera
    apply(a);
  }
  drawTimeline(display, bottom);
  if (showWhatIf_) drawWhatIfControls();
  if (showHelp_) drawHelp();
  if (const auto path = dialog_.draw()) reopen(*path);
}

// [SECTION] menu bar -------------------------------------------------------------------------

float RecordingDebugger::drawMenuBar() {
  if (!ImGui::BeginMainMenuBar()) return 0.0f;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("Open recording...", "Ctrl+O")) dialog_.open();
    if (ImGui::MenuItem("Validate again")) validation_.start(path_, pinned_);
    if (ImGui::MenuItem("Close recording (back to the scenes)")) close_ = true;
    ImGui::Separator();
    if (ImGui::MenuItem("Quit", "Ctrl+Q")) quit_ = true;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Time")) {
    if (ImGui::MenuItem(paused_ ? "Play" : "Pause", "Space")) paused_ = !paused_;
    if (ImGui::MenuItem("Next frame", ".")) goTo(session_->frame() + 1);
    if (ImGui::MenuItem("Previous frame", ",") && session_->frame() > 0)
      goTo(session_->frame() - 1);
    if (ImGui::MenuItem("Next call", "Down")) stepCall(+1);
    if (ImGui::MenuItem("Previous call", "Up")) stepCall(-1);
    if (ImGui::MenuItem("End of frame", "Esc")) selectCall(std::nullopt);
    if (ImGui::MenuItem("First frame", "R")) goTo(0);
    ImGui::Separator();
    for (const double s : {0.25, 0.5, 1.0, 2.0, 4.0}) {
      char label[16];
      std::snprintf(label, sizeof label, "%gx", s);
      if (ImGui::MenuItem(label, nullptr, speed_ == s)) speed_ = s;
    }
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    if (ImGui::MenuItem("Frame everything", "Home")) frameAll();
    if (ImGui::MenuItem("Follow the traced item", "F", follow_)) {
      follow_ = !follow_;
      if (!follow_) frameAll();
    }
    if (ImGui::MenuItem("Items (outliner)", "I")) state_.showTab = 1;
    if (ImGui::BeginMenu("Overlays")) {
      for (const ui::OverlayToggle& t : ui::overlayToggles()) {
        ImGui::MenuItem(t.name, nullptr, &(state_.view.overlays.*t.flag));
      }
      ImGui::EndMenu();
    }
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("What-if")) {
    if (ImGui::MenuItem("Re-run under another mover...", "W", showWhatIf_))
      showWhatIf_ = !showWhatIf_;
    if (ImGui::MenuItem("Back to the recorded run only", nullptr, false, whatIf_ != nullptr))
      whatIf_.reset();
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    if (ImGui::MenuItem("Shortcuts and mouse", "F1", showHelp_)) showHelp_ = !showHelp_;
    ImGui::EndMenu();
  }
  const float h = ImGui::GetWindowHeight();
  ImGui::EndMainMenuBar();
  return h;
}

// [SECTION] timeline -------------------------------------------------------------------------

void RecordingDebugger::drawTimeline(ImVec2 display, float h) {
  ImGui::SetNextWindowPos({0.0f, display.y - h}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({display.x, h}, ImGuiCond_Always);
  if (!ImGui::Begin("Timeline", nullptr,
                    kFixed | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar)) {
    ImGui::End();
    return;
  }
  const std::uint64_t frame = session_->frame();
  if (ImGui::Button("Back (,)") && frame > 0) {
    paused_ = true;
    goTo(frame - 1);
  }
  ImGui::SameLine();
  if (ImGui::Button(paused_ ? "Play (Space)" : "Pause (Space)")) {
    paused_ = !paused_;
    if (!paused_ && frame == session_->lastFrame()) goTo(0);
  }
  ImGui::SameLine();
  if (ImGui::Button("Forward (.)")) {
    paused_ = true;
    goTo(frame + 1);
  }
  ImGui::SameLine();
  if (ImGui::Button("Call ^")) stepCall(-1);
  ImGui::SameLine();
  if (ImGui::Button("Call v")) stepCall(+1);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90.0f);
  float speed = static_cast<float>(speed_);
  if (ImGui::SliderFloat("##speed", &speed, 0.25f, 4.0f, "%.2fx", ImGuiSliderFlags_Logarithmic)) {
    // A typed rate is not clamped by the slider: one outside 0.25x..4x (a negative one left the
    // player stuck "playing") is refused and the rate stays.
    if (std::isfinite(speed) && speed >= 0.25f && speed <= 4.0f) {
      speed_ = static_cast<double>(speed);
    } else {
      char why[96];
      std::snprintf(why, sizeof why, "playback rate %gx refused: it is 0.25x to 4x",
                    static_cast<double>(speed));
      message_ = why;
    }
  }
  ImGui::SameLine();
  ImGui::Text("frame %" PRIu64 " (0..%" PRIu64 ")", frame, session_->lastFrame());

  TimelineMarks marks;
  marks.unit = "frame";
  marks.known = validation_.done() ? session_->lastFrame() : validation_.progress();
  const auto divergence = validation_.divergence();
  ImGui::SameLine();
  if (!message_.empty()) {
    ImGui::TextColored(colour(pal::kBad), "|  %s", message_.c_str());
  } else if (validation_.running()) {
    ImGui::TextColored(colour(pal::kDim), "|  validating: frame %" PRIu64 " of %" PRIu64,
                       validation_.progress(), session_->frames());
  } else if (!validation_.error().empty()) {
    ImGui::TextColored(colour(pal::kBad), "|  not validated: %s", validation_.error().c_str());
  } else if (divergence) {
    marks.failure = divergence->frame;
    marks.failureText = "diverged: " + divergence->what + " of " + divergence->item;
    ImGui::TextColored(colour(pal::kBad), "|  DIVERGED at frame %" PRIu64 ", call %u (%s %s)",
                       divergence->frame, divergence->call, divergence->item.c_str(),
                       divergence->what.c_str());
    ImGui::SameLine();
    if (ImGui::SmallButton("go##divergence")) {
      paused_ = true;
      goTo(divergence->frame);
      selectCall(divergence->call);
    }
  } else if (validation_.done()) {
    const ReplaySummary& summary = session_->replay().summary();
    if (summary.damagedAt) {
      // Only what could be read was checked: not a verdict on the whole file.
      ImGui::TextColored(colour(pal::kBad),
                         "|  the file is cut or damaged at byte %" PRIu64
                         ": only frames 0..%" PRIu64 " were checked, and they match",
                         *summary.damagedAt, summary.frames - 1);
    } else {
      ImGui::TextColored(colour(pal::kGood), "|  valid: the replay matches the recording");
    }
  }
  std::optional<std::uint64_t> implausible;
  if (whatIf_) {
    if (const auto r = whatIf_->job.report()) {
      marks.difference = r->firstDifferentFrame;
      implausible = r->firstImplausibleFrame;
    }
  }
  const std::uint64_t last = std::max<std::uint64_t>(session_->lastFrame(), 1);
  const float width = ImGui::GetContentRegionAvail().x;
  const auto to = timelineBar("##timeline", frame, last, marks, width);
  // The frame where the game's next goal stops making sense, on the same bar (violet).
  if (implausible && *implausible <= last) {
    const ImVec2 p = ImGui::GetItemRectMin(), q = ImGui::GetItemRectMax();
    const float w = q.x - p.x;
    const float x =
        p.x + 4.0f +
        static_cast<float>(static_cast<double>(*implausible) / static_cast<double>(last)) *
            (w - 8.0f);
    ImDrawList& dl = *ImGui::GetWindowDrawList();
    dl.AddLine({x, p.y}, {x, q.y}, pal::kImplausible, 2.0f);
    dl.AddTriangleFilled({x - 5.0f, q.y}, {x + 5.0f, q.y}, {x, q.y - 6.0f}, pal::kImplausible);
  }
  if (to) {
    paused_ = true;
    if (*to != frame) goTo(*to);
  }
  ImGui::End();
}

// [SECTION] what-if --------------------------------------------------------------------------

void RecordingDebugger::drawWhatIfSideBySide(ImVec2 origin, ImVec2 size) {
  WhatIf& w = *whatIf_;
  w.view.overlays = state_.view.overlays;
  w.view.paused = paused_;
  const std::optional<WhatIfReport> report = w.job.report();
  const ui::WhatIfStatus status{report ? &*report : nullptr, w.job.running(), w.job.error()};
  ui::WhatIfPair pair{*session_, state_, *w.session, w.view, w.mover, w.updatesAsMoves};
  const ui::WhatIfActions a = ui::whatIfLayout(pair, status, origin, size);
  if (a.cameraMoved) follow_ = false;
  if (a.goTo) {
    paused_ = true;
    goTo(a.goTo->first);
    if (a.goTo->second) selectCall(*a.goTo->second);
  }
  apply(a.recording);
}

void RecordingDebugger::drawWhatIfControls() {
  ImGui::SetNextWindowSize({420, 0}, ImGuiCond_Always);
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, {0.5f, 0.5f});
  if (!ImGui::Begin("What-if: re-run the recording (W)", &showWhatIf_,
                    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  ImGui::TextWrapped(
      "Every recorded move is made again by another mover, beside the recorded "
      "run.");
  ImGui::SetNextItemWidth(200.0f);
  if (ImGui::BeginCombo("mover", draftMover_.name().c_str())) {
    for (const MoverEntry& m : moverTable()) {
      const std::string name(m.name);
      if (ImGui::Selectable(name.c_str(), name == draftMover_.name())) draftMover_ = m.spec;
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(m.description).c_str());
    }
    ImGui::EndCombo();
  }
  const bool substep = draftMover_.kind == MoverKind::substep;
  ImGui::BeginDisabled(!substep);
  ImGui::SetNextItemWidth(200.0f);
  const double lo = 0.0, hi = 1e6;
  ImGui::DragScalar("substep length", ImGuiDataType_Double, &draftSubstep_, 0.25f, &lo, &hi,
                    draftSubstep_ == 0.0 ? "half the smallest item" : "%.3g");
  ImGui::EndDisabled();
  ImGui::Checkbox("treat a body's updates as moves", &draftUpdates_);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "for games that move bodies themselves (x += v*dt, update, push out):\n"
        "each update that only changes a position is re-run as a move");
  }
  if (ImGui::Button("Run")) {
    MoverSpec m = draftMover_;
    if (substep) m.maxStep = draftSubstep_;
    startWhatIf(m, draftUpdates_);
  }
  ImGui::SameLine();
  if (ImGui::Button("Recorded run only") && whatIf_) whatIf_.reset();
  ImGui::PushStyleColor(ImGuiCol_Text, pal::kDim);
  ImGui::TextWrapped("%s", ui::kOpenLoop);
  ImGui::PopStyleColor();
  ImGui::End();
}

// [SECTION] help -----------------------------------------------------------------------------

void RecordingDebugger::drawHelp() {
  struct Row {
    const char* keys;
    const char* what;
  };
  static constexpr Row kRows[] = {
      {"Space, P", "play / pause the recording"},
      {". O  ,", "next frame, previous frame"},
      {"Down, Up", "next / previous call (across frames)"},
      {"Esc", "the frame's end (no call selected)"},
      {"R", "first frame"},
      {"-  =", "slower / faster (0.25x-4x)"},
      {"Home, F", "frame everything, follow the traced item"},
      {"I", "the Items tab (outliner, with search)"},
      {"W", "what-if: re-run the recording under another mover"},
      {"Ctrl+O", "open another recording (or drop a file on the window)"},
      {"F1, Ctrl+Q", "this window, quit"},
      {"wheel, right drag", "zoom about the cursor, pan"},
      {"left click", "trace the item under the cursor"},
      {"timeline",
       "click or drag to scrub; red: divergence, orange: what-if differs, "
       "violet: goals stop making sense"},
  };
  ImGui::SetNextWindowSize({560, 0}, ImGuiCond_Always);
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, {0.5f, 0.5f});
  ImGui::SetNextWindowBgAlpha(1.0f);  // over the views: nothing beneath may show through
  if (ImGui::Begin("Help: recordings", &showHelp_,
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    if (ImGui::BeginTable("keys", 2)) {
      ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed,
                              ImGui::CalcTextSize("wheel, right drag").x + 8.0f);
      ImGui::TableSetupColumn("what", ImGuiTableColumnFlags_WidthStretch);
      for (const Row& r : kRows) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextColored(colour(pal::kRender), "%s", r.keys);
        ImGui::TableNextColumn();
        ImGui::TextWrapped("%s", r.what);
      }
      ImGui::EndTable();
    }
  }
  ImGui::End();
}

}  // namespace tv::viewer
