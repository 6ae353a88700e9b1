// The what-if view: the recorded run and its re-run side by side, and the report. Drawn live by
// the debugger and as a still by tv-render --open FILE --what-if MOVER.
#include "tv/ui/what_if_view.hpp"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>

#include "tv/ui/palette.hpp"

namespace tv::ui {

namespace pal = palette;

const char* const kOpenLoop =
    "Open-loop: the game's recorded goals are replayed as they were; how the game would have "
    "reacted to a different outcome is not in the file.";

namespace {

constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                    ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                    ImGuiWindowFlags_NoFocusOnAppearing;

ImVec4 colour(ImU32 c) {
  return ImGui::ColorConvertU32ToFloat4(c);
}

// The report of the whole re-run: totals, the first frames that differ, and every move that
// ended elsewhere (a row selects it).
void reportContents(const WhatIfPair& p, const WhatIfStatus& status, WhatIfActions& actions) {
  ImGui::TextWrapped("%s", kOpenLoop);
  if (status.running) {
    ImGui::TextColored(colour(pal::kDim), "re-running the whole recording with %s...",
                       p.mover.name().c_str());
    return;
  }
  if (!status.error.empty()) {
    ImGui::TextColored(colour(pal::kBad), "%s", status.error.c_str());
    return;
  }
  const WhatIfReport* r = status.report;
  if (!r) return;
  ImGui::TextWrapped("%" PRIu64 " moves re-run with %s; %zu ended elsewhere", r->moves,
                     moverLabel(p.mover).c_str(), r->differences.size());
  const auto goButton = [&](const char* id, std::uint64_t f) {
    ImGui::SameLine();
    if (ImGui::SmallButton(id)) actions.goTo = std::make_pair(f, std::optional<std::uint32_t>{});
  };
  if (r->firstDifferentFrame) {
    ImGui::TextColored(colour(pal::kRender), "runs first differ at frame %" PRIu64,
                       *r->firstDifferentFrame);
    goButton("go##first", *r->firstDifferentFrame);
  } else {
    ImGui::TextColored(colour(pal::kGood), "the runs never differ");
  }
  if (r->firstImplausibleFrame) {
    ImGui::TextColored(colour(pal::kImplausible),
                       "from frame %" PRIu64 " the game's goals stop making sense",
                       *r->firstImplausibleFrame);
    goButton("go##implausible", *r->firstImplausibleFrame);
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
      if (ImGui::Selectable(label, false, ImGuiSelectableFlags_SpanAllColumns))
        actions.goTo = std::make_pair(d.frame, std::optional<std::uint32_t>{d.call});
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(p.recorded.describe(d.item).c_str());
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

}  // namespace

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

WhatIfActions whatIfLayout(WhatIfPair& p, const WhatIfStatus& status, ImVec2 origin,
                           ImVec2 size) {
  WhatIfActions actions;
  const float side = std::clamp(size.x * 0.32f, 320.0f, 460.0f);
  const float panels = size.x - side;
  // One line across both panels: what this comparison is, and that it is open-loop.
  ImGui::SetNextWindowPos(origin, ImGuiCond_Always);
  ImGui::SetNextWindowSize({panels, 0}, ImGuiCond_Always);
  float titleH = 0.0f;
  if (ImGui::Begin("WhatIfTitle", nullptr,
                   ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                       ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing)) {
    ImGui::Text("%s   frame %" PRIu64 "   recorded run  vs  %s%s", p.recorded.name().c_str(),
                p.recorded.frame(), moverLabel(p.mover).c_str(),
                p.updatesAsMoves ? " (updates treated as moves)" : "");
    ImGui::PushStyleColor(ImGuiCol_Text, pal::kRender);
    ImGui::TextWrapped("%s", kOpenLoop);
    ImGui::PopStyleColor();
    titleH = ImGui::GetWindowHeight();
  }
  ImGui::End();

  const float half = std::floor(panels * 0.5f);
  const float h = std::max(size.y - titleH, 80.0f);
  RecordingSession* sessions[2] = {&p.recorded, &p.whatIf};
  DebuggerState* views[2] = {&p.recordedState.view, &p.whatIfView};
  const std::string names[2] = {"recorded###RecordedPanel",
                                "what-if: " + moverLabel(p.mover) + "###WhatIfPanel"};
  std::optional<ItemId> picked;
  for (int k = 0; k < 2; ++k) {
    ImGui::SetNextWindowPos({origin.x + half * static_cast<float>(k), origin.y + titleH},
                            ImGuiCond_Always);
    ImGui::SetNextWindowSize({half, h}, ImGuiCond_Always);
    if (ImGui::Begin(names[k].c_str(), nullptr, kFixed | ImGuiWindowFlags_NoScrollbar)) {
      const float stats = ImGui::GetTextLineHeightWithSpacing() * 2.0f + 4.0f;
      const ImVec2 avail = ImGui::GetContentRegionAvail();
      if (auto pick = recordingWorldView("##world", *sessions[k], *views[k],
                                         {avail.x, std::max(avail.y - stats, 40.0f)})) {
        picked = pick;
      }
      const MoveTrace* m = sessions[k]->callTrace();
      if (!m && !sessions[k]->history().empty()) m = &sessions[k]->history().back().trace;
      if (m) {
        ImGui::Text("%s ended at (%.3f, %.3f), %zu hits", sessions[k]->describe(m->item).c_str(),
                    m->final.x, m->final.y, m->hits.size());
        if (k == 1) {
          const MoveTrace* r = p.recorded.callTrace();
          if (!r && !p.recorded.history().empty()) r = &p.recorded.history().back().trace;
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
    views[k]->frameView = view;
    actions.cameraMoved = true;
    break;
  }

  if (picked) actions.recording.item = *picked;
  ImGui::SetNextWindowPos({origin.x + panels, origin.y}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({side, size.y}, ImGuiCond_Always);
  if (ImGui::Begin("WhatIfSide", nullptr, kFixed | ImGuiWindowFlags_NoTitleBar)) {
    if (ImGui::BeginTabBar("whatif")) {
      if (ImGui::BeginTabItem("What-if report")) {
        reportContents(p, status, actions);
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Calls")) {
        ImGui::BeginChild("calls");
        recordingCallsContents(p.recorded, p.recordedState, actions.recording);
        ImGui::EndChild();
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Inspector (what-if)")) {
        ImGui::BeginChild("inspector");
        recordingInspectorContents(p.whatIf);
        ImGui::EndChild();
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Items")) {
        recordingOutlinerContents(p.recorded, p.recordedState, actions.recording);
        ImGui::EndTabItem();
      }
      ImGui::EndTabBar();
    }
  }
  ImGui::End();
  return actions;
}

std::optional<WhatIfFailure> firstFailure(const WhatIfReport& report) {
  for (const MoveDifference& d : report.differences) {
    if (d.tunnelled || d.overlapping) return WhatIfFailure{d.frame, d.call, d.item, d.tunnelled};
  }
  return std::nullopt;
}

WhatIfReport runWhatIf(const std::string& path, const MoverSpec& mover, bool updatesAsMoves,
                       double farAway) {
  ReplayOptions o;
  o.mover = mover;
  o.updatesAsMoves = updatesAsMoves;
  o.tolerant = true;
  Replay replay = Replay::open(path, o);
  return replay.whatIf(farAway);
}

}  // namespace tv::ui
