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

namespace tv::viewer {

namespace pal = ui::palette;

namespace {

constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                    ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                    ImGuiWindowFlags_NoFocusOnAppearing;
constexpr ImU32 kImplausible = IM_COL32(200, 120, 255, 255);
constexpr const char* kOpenLoop =
    "Open-loop: the game's recorded goals are replayed as they were; how the game would have "
    "reacted to a different outcome is not in the file.";

ImVec4 colour(ImU32 c) {
  return ImGui::ColorConvertU32ToFloat4(c);
}

// "substep-discrete (8 px pieces)": the name, and the piece length where it has one.
std::string moverLabel(const MoverSpec& m) {
  if (m.kind != MoverKind::substep) return m.name();
  char text[96];
  if (m.maxStep == 0.0) {
    std::snprintf(text, sizeof text, "%s (pieces of half the smallest item)", m.name().c_str());
  } else {
    std::snprintf(text, sizeof text, "%s (%g px pieces)", m.name().c_str(), m.maxStep);
  }
  return text;
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
    dl.AddLine({x, p.y}, {x, q.y}, kImplausible, 2.0f);
    dl.AddTriangleFilled({x - 5.0f, q.y}, {x + 5.0f, q.y}, {x, q.y - 6.0f}, kImplausible);
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
  const float side = std::clamp(size.x * 0.32f, 320.0f, 460.0f);
  const float panels = size.x - side;
  // One line across both panels: what this comparison is, and that it is open-loop.
  ImGui::SetNextWindowPos(origin, ImGuiCond_Always);
  ImGui::SetNextWindowSize({panels, 0}, ImGuiCond_Always);
  float titleH = 0.0f;
  if (ImGui::Begin("WhatIfTitle", nullptr,
                   ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                       ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing)) {
    ImGui::Text("%s   frame %" PRIu64 "   recorded run  vs  %s%s", session_->name().c_str(),
                session_->frame(), moverLabel(w.mover).c_str(),
                w.updatesAsMoves ? " (updates treated as moves)" : "");
    ImGui::PushStyleColor(ImGuiCol_Text, pal::kRender);
    ImGui::TextWrapped("%s", kOpenLoop);
    ImGui::PopStyleColor();
    titleH = ImGui::GetWindowHeight();
  }
  ImGui::End();

  const float half = std::floor(panels * 0.5f);
  const float h = std::max(size.y - titleH, 80.0f);
  ui::RecordingSession* sessions[2] = {session_.get(), w.session.get()};
  ui::DebuggerState* views[2] = {&state_.view, &w.view};
  const std::string names[2] = {"recorded###RecordedPanel",
                                "what-if: " + moverLabel(w.mover) + "###WhatIfPanel"};
  std::optional<ItemId> picked;
  for (int k = 0; k < 2; ++k) {
    ImGui::SetNextWindowPos({origin.x + half * static_cast<float>(k), origin.y + titleH},
                            ImGuiCond_Always);
    ImGui::SetNextWindowSize({half, h}, ImGuiCond_Always);
    if (ImGui::Begin(names[k].c_str(), nullptr, kFixed | ImGuiWindowFlags_NoScrollbar)) {
      const float stats = ImGui::GetTextLineHeightWithSpacing() * 2.0f + 4.0f;
      const ImVec2 avail = ImGui::GetContentRegionAvail();
      if (auto pick = ui::recordingWorldView("##world", *sessions[k], *views[k],
                                             {avail.x, std::max(avail.y - stats, 40.0f)})) {
        picked = pick;
      }
      const MoveTrace* m = sessions[k]->callTrace();
      if (!m && !sessions[k]->history().empty()) m = &sessions[k]->history().back().trace;
      if (m) {
        ImGui::Text("%s ended at (%.3f, %.3f), %zu hits", sessions[k]->describe(m->item).c_str(),
                    m->final.x, m->final.y, m->hits.size());
        if (k == 1) {
          const MoveTrace* r = session_->callTrace();
          if (!r && !session_->history().empty()) r = &session_->history().back().trace;
          if (r) {
            const double d = std::hypot(m->final.x - r->final.x, m->final.y - r->final.y);
            ImGui::TextColored(colour(d > 0.0 ? pal::kRender : pal::kGood),
                               d > 0.0 ? "%.3f from the recorded end" : "same end as recorded", d);
          }
        }
      } else if (const auto id = sessions[k]->selected(); id && sessions[k]->world().has(*id)) {
        // Moved by update (a game that moves bodies itself): nothing was swept to trace.
        const Rect r = sessions[k]->world().rect(*id);
        ImGui::Text("%s at (%.3f, %.3f), no move traced", sessions[k]->describe(*id).c_str(), r.x,
                    r.y);
      } else {
        ImGui::TextColored(colour(pal::kDim), "select a call or an item to trace");
      }
    }
    ImGui::End();
  }
  // One camera for both panels: a zoom or pan in either applies to the other.
  for (int k = 0; k < 2; ++k) {
    if (views[k]->frameView) continue;
    const Rect view = views[k]->camera.view();
    views[1 - k]->frameView = view;
    if (follow_) follow_ = false;
    views[k]->frameView = view;
    break;
  }

  ui::RecordingActions a;
  if (picked) a.item = *picked;
  ImGui::SetNextWindowPos({origin.x + panels, origin.y}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({side, size.y}, ImGuiCond_Always);
  if (ImGui::Begin("WhatIfSide", nullptr, kFixed | ImGuiWindowFlags_NoTitleBar)) {
    if (ImGui::BeginTabBar("whatif")) {
      if (ImGui::BeginTabItem("What-if report")) {
        drawWhatIfReport();
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Calls")) {
        ImGui::BeginChild("calls");
        ui::recordingCallsContents(*session_, state_, a);
        ImGui::EndChild();
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Inspector (what-if)")) {
        ImGui::BeginChild("inspector");
        ui::recordingInspectorContents(*w.session);
        ImGui::EndChild();
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Items")) {
        ui::recordingOutlinerContents(*session_, state_, a);
        ImGui::EndTabItem();
      }
      ImGui::EndTabBar();
    }
  }
  ImGui::End();
  apply(a);
}

void RecordingDebugger::drawWhatIfReport() {
  WhatIf& w = *whatIf_;
  ImGui::TextWrapped("%s", kOpenLoop);
  if (w.job.running()) {
    ImGui::TextColored(colour(pal::kDim), "re-running the whole recording with %s...",
                       w.mover.name().c_str());
    return;
  }
  if (!w.job.error().empty()) {
    ImGui::TextColored(colour(pal::kBad), "%s", w.job.error().c_str());
    return;
  }
  const auto r = w.job.report();
  if (!r) return;
  ImGui::TextWrapped("%" PRIu64 " moves re-run with %s; %zu ended elsewhere", r->moves,
                     moverLabel(w.mover).c_str(), r->differences.size());
  const auto goButton = [&](const char* id, std::uint64_t f, std::optional<std::uint32_t> call) {
    ImGui::SameLine();
    if (ImGui::SmallButton(id)) {
      paused_ = true;
      goTo(f);
      if (call) selectCall(call);
    }
  };
  if (r->firstDifferentFrame) {
    ImGui::TextColored(colour(pal::kRender), "runs first differ at frame %" PRIu64,
                       *r->firstDifferentFrame);
    goButton("go##first", *r->firstDifferentFrame, std::nullopt);
  } else {
    ImGui::TextColored(colour(pal::kGood), "the runs never differ");
  }
  if (r->firstImplausibleFrame) {
    ImGui::TextColored(colour(kImplausible),
                       "from frame %" PRIu64 " the game's goals stop making sense",
                       *r->firstImplausibleFrame);
    goButton("go##implausible", *r->firstImplausibleFrame, std::nullopt);
    ImGui::TextColored(colour(pal::kDim),
                       "(a re-run body is far from where the recording goes on)");
  }
  ImGui::TextColored(colour(r->tunnelled ? pal::kBad : pal::kGood),
                     "tunnelled: %" PRIu64 "   ended overlapping a solid: %" PRIu64, r->tunnelled,
                     r->overlapping);
  ImGui::PushStyleColor(ImGuiCol_Text, r->recordedTunnelled ? pal::kBad : pal::kDim);
  ImGui::TextWrapped("the recorded run: tunnelled %" PRIu64 ", ended overlapping %" PRIu64,
                     r->recordedTunnelled, r->recordedOverlapping);
  ImGui::PopStyleColor();
  if (r->failedCalls > 0) {
    ImGui::TextColored(colour(pal::kRender), "%" PRIu64 " calls refused by the re-run world",
                       r->failedCalls);
  }
  const ImGuiTableFlags flags = ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg |
                                ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_BordersInnerV;
  if (!ImGui::BeginTable("differences", 4, flags)) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn("frame.call");
  ImGui::TableSetupColumn("item");
  ImGui::TableSetupColumn("by");
  ImGui::TableSetupColumn("what");
  ImGui::TableHeadersRow();
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(r->differences.size()));
  while (clipper.Step()) {
    for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
      const MoveDifference& d = r->differences[static_cast<std::size_t>(i)];
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      char label[48];
      std::snprintf(label, sizeof label, "%" PRIu64 ".%u##d%d", d.frame, d.call, i);
      if (ImGui::Selectable(label, false, ImGuiSelectableFlags_SpanAllColumns)) {
        paused_ = true;
        goTo(d.frame);
        selectCall(d.call);
      }
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(session_->describe(d.item).c_str());
      ImGui::TableNextColumn();
      // Enough digits that a rounding-sized difference does not read as 0.000.
      ImGui::Text("%.4g", d.distance);
      ImGui::TableNextColumn();
      if (d.tunnelled) {
        ImGui::TextColored(colour(pal::kBad), "tunnelled");
      } else if (d.overlapping) {
        ImGui::TextColored(colour(pal::kBad), "overlapping");
      } else {
        ImGui::TextColored(colour(pal::kDim), "elsewhere");
      }
    }
  }
  ImGui::EndTable();
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
  ImGui::TextWrapped("%s", kOpenLoop);
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
