// A recording's view: world, calls, outliner, inspector, HUD and their layout.
//
// [SECTION] world view
// [SECTION] calls
// [SECTION] outliner
// [SECTION] inspector
// [SECTION] HUD and layout
#include "tv/ui/recording_view.hpp"

#include <algorithm>
#include <cctype>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <vector>

#include "draw_util.hpp"
#include "windows.hpp"
#include "tv/ui/palette.hpp"

namespace tv::ui {

namespace pal = palette;

namespace {

using detail::beginCanvas;
using detail::kFixed;
using detail::kMargin;
using detail::kOverlay;
using detail::place;

ImVec4 colour(ImU32 c) {
  return ImGui::ColorConvertU32ToFloat4(c);
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string responseText(const World& world, ResponseId r) {
  if (r == response::ignore) return "ignore";
  if (r < response::kBuiltinCount) return std::string(world.responseName(r));
  // A user response registered later than this frame would not be known to the world here.
  try {
    return std::string(world.responseName(r));
  } catch (const std::exception&) {
    return "response " + std::to_string(r);
  }
}

}  // namespace

// [SECTION] world view -----------------------------------------------------------------------

std::optional<ItemId> recordingWorldView(const char* id, RecordingSession& session,
                                         DebuggerState& st, ImVec2 size) {
  const ImVec2 pos = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton(id, size,
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  if (st.frameView) {
    const float top = std::min(st.coveredTop, size.y * 0.4f);
    const float bottom = std::min(st.coveredBottom, size.y * 0.4f);
    st.camera.frame(*st.frameView, pos, size, {pos.x, pos.y + top},
                    {size.x, size.y - top - bottom});
  } else {
    st.camera.place(pos, size);
  }
  std::optional<ItemId> clicked;
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f) {
    st.camera.zoom(std::pow(1.2, static_cast<double>(io.MouseWheel)), io.MousePos);
    st.frameView.reset();
  }
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Right)) {
    st.camera.pan(io.MouseDelta);
    st.frameView.reset();
  }
  if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
    clicked = session.itemAt(st.camera.toWorld(io.MousePos));
  }
  if (ImGui::IsItemHovered()) {
    if (const auto under = session.itemAt(st.camera.toWorld(io.MousePos))) {
      ImGui::SetTooltip("%s  (click to trace)", session.describe(*under).c_str());
    }
  }
  const WorldPicture pic = session.picture();
  drawWorld(*ImGui::GetWindowDrawList(), st.camera, pic, st.overlays);
  return clicked;
}

// [SECTION] calls ----------------------------------------------------------------------------

void recordingCallsContents(const RecordingSession& s, RecordingViewState& st,
                            RecordingActions& a) {
  const auto calls = s.calls();
  if (calls.empty()) {
    ImGui::TextColored(colour(pal::kDim), "no calls in this frame");
    return;
  }
  const bool frameEnd = !s.call();
  if (ImGui::Selectable("   end of frame (every call made)", frameEnd)) a.call = std::nullopt;
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(calls.size()));
  if (st.revealCall && s.call())
    clipper.ForceDisplayRangeByIndices(static_cast<int>(*s.call()),
                                       static_cast<int>(*s.call()) + 1);
  while (clipper.Step()) {
    for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
      const CallInfo& c = calls[static_cast<std::size_t>(i)];
      const bool on = s.call() && *s.call() == static_cast<std::uint32_t>(i);
      const bool mine = s.selected() && c.item.valid() && c.item == *s.selected();
      char label[320];
      std::snprintf(label, sizeof label, "%3d %s##call%d", i, c.summary.c_str(), i);
      // The traced item's calls stand out; a move that hit something is red-tinted.
      ImU32 tint = mine ? pal::kLabel : pal::kDim;
      if (tracesAMove(c.kind) && c.hits > 0) tint = mine ? pal::kHit : IM_COL32(200, 120, 120, 255);
      ImGui::PushStyleColor(ImGuiCol_Text, tint);
      if (ImGui::Selectable(label, on))
        a.call = on ? std::nullopt : std::optional<std::uint32_t>(i);
      ImGui::PopStyleColor();
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", c.summary.c_str());
      if (on && st.revealCall) {
        ImGui::SetScrollHereY(0.5f);
        st.revealCall = false;
      }
    }
  }
}

// [SECTION] outliner -------------------------------------------------------------------------

void recordingOutlinerContents(const RecordingSession& s, RecordingViewState& st,
                               RecordingActions& a) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "%s", st.itemFilter.c_str());
  ImGui::SetNextItemWidth(-120.0f);
  if (ImGui::InputTextWithHint("##items", "search label or category", buffer, sizeof buffer)) {
    st.itemFilter = buffer;
  }
  ImGui::SameLine();
  ImGui::Checkbox("moving only", &st.movingOnly);
  const std::string needle = lower(st.itemFilter);
  std::vector<const RecordedItem*> shown;
  for (const RecordedItem& i : s.replay().items()) {
    if (st.movingOnly && i.moves == 0) continue;
    if (!needle.empty() && lower(i.label + " " + i.category).find(needle) == std::string::npos)
      continue;
    shown.push_back(&i);
  }
  // By category, then label: the player and the bullets together, the tiles after.
  std::stable_sort(shown.begin(), shown.end(), [](const RecordedItem* x, const RecordedItem* y) {
    if (x->category != y->category) return x->category < y->category;
    return x->moves > y->moves;
  });
  ImGui::TextColored(colour(pal::kDim), "%zu of %zu items", shown.size(),
                     s.replay().items().size());
  const ImGuiTableFlags flags = ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg |
                                ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_BordersInnerV;
  if (!ImGui::BeginTable("outliner", 4, flags)) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn("label", ImGuiTableColumnFlags_WidthStretch, 3.0f);
  ImGui::TableSetupColumn("category", ImGuiTableColumnFlags_WidthStretch, 2.0f);
  ImGui::TableSetupColumn("moves", ImGuiTableColumnFlags_WidthStretch, 1.0f);
  ImGui::TableSetupColumn("hits", ImGuiTableColumnFlags_WidthStretch, 1.0f);
  ImGui::TableHeadersRow();
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(shown.size()));
  while (clipper.Step()) {
    for (int r = clipper.DisplayStart; r < clipper.DisplayEnd; ++r) {
      const RecordedItem& i = *shown[static_cast<std::size_t>(r)];
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      const bool on = s.selected() && *s.selected() == i.id;
      ImGui::PushID(r);
      if (ImGui::Selectable(i.label.c_str(), on, ImGuiSelectableFlags_SpanAllColumns)) {
        a.item = on ? std::nullopt : std::optional<ItemId>(i.id);
      }
      ImGui::PopID();
      if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("frames %" PRIu64 "..%" PRIu64 ", longest move %.2f, %" PRIu64
                          " moves ended overlapping a solid",
                          i.firstFrame, i.lastFrame, i.maxSpeed, i.endedOverlapping);
      }
      ImGui::TableNextColumn();
      ImGui::TextColored(colour(pal::kDim), "%s", i.category.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%" PRIu64, i.moves);
      ImGui::TableNextColumn();
      ImGui::Text("%" PRIu64, i.hits);
    }
  }
  ImGui::EndTable();
}

// [SECTION] inspector ------------------------------------------------------------------------

namespace {

void traceDetails(const RecordingSession& s, const MoveTrace& m) {
  const World& w = s.world();
  ImGui::Text("(%.3f, %.3f) -> goal (%.3f, %.3f)", m.start.x, m.start.y, m.goal.x, m.goal.y);
  ImGui::Text("ended at (%.3f, %.3f)%s%s", m.final.x, m.final.y, m.mover.empty() ? "" : "  by ",
              std::string(m.mover).c_str());
  if (ImGui::TreeNodeEx("cells", 0, "cells visited: %zu", m.cells.size())) {
    std::string line;
    for (std::size_t k = 0; k < m.cells.size(); ++k) {
      char cell[48];
      std::snprintf(cell, sizeof cell, "(%lld,%lld) ", static_cast<long long>(m.cells[k].x),
                    static_cast<long long>(m.cells[k].y));
      line += cell;
      if ((k + 1) % 6 == 0 || k + 1 == m.cells.size()) {
        ImGui::TextUnformatted(line.c_str());
        line.clear();
      }
    }
    ImGui::TreePop();
  }
  // Each candidate once, with what the recorded filter answered for it (if it was asked:
  // only items the move would meet first are).
  std::vector<ItemId> seen;
  for (const ItemId id : m.candidates) {
    if (std::find(seen.begin(), seen.end(), id) == seen.end()) seen.push_back(id);
  }
  if (ImGui::TreeNodeEx("candidates", ImGuiTreeNodeFlags_DefaultOpen,
                        "candidates tested: %zu (%zu distinct)", m.candidates.size(),
                        seen.size())) {
    for (const ItemId id : seen) {
      std::string answers;
      for (const TraceAnswer& ans : m.answers) {
        if (ans.other != id) continue;
        answers += (answers.empty() ? "" : ", ") + responseText(w, ans.response);
      }
      ImGui::TextColored(colour(pal::kCandidate), "%s", s.describe(id).c_str());
      ImGui::SameLine();
      if (answers.empty()) {
        ImGui::TextColored(colour(pal::kDim), "filter not asked (not met first)");
      } else {
        ImGui::Text("filter: %s", answers.c_str());
      }
    }
    ImGui::TreePop();
  }
  if (ImGui::TreeNodeEx("legs", ImGuiTreeNodeFlags_DefaultOpen, "sweeps: %zu", m.legs.size())) {
    for (std::size_t k = 0; k < m.legs.size(); ++k) {
      const TraceLeg& l = m.legs[k];
      ImGui::TextColored(colour(pal::kSweep), "leg %zu", k + 1);
      ImGui::SameLine();
      ImGui::Text("(%.3f, %.3f) -> (%.3f, %.3f)", l.start.x, l.start.y, l.goal.x, l.goal.y);
    }
    if (!m.substeps.empty()) {
      ImGui::TextColored(colour(pal::kSubstep), "%zu substep boundaries", m.substeps.size());
    }
    ImGui::TreePop();
  }
  for (std::size_t h = 0; h < m.hits.size(); ++h) {
    const Collision& c = m.hits[h];
    char ti[32];
    std::snprintf(ti, sizeof ti, c.overlaps ? "overlapping" : "ti %.4f", c.ti);
    ImGui::TextColored(colour(pal::kHit), "hit %zu", h + 1);
    ImGui::SameLine();
    ImGui::Text("%s  %s  normal %+.0f,%+.0f%s", s.describe(c.other).c_str(), ti, c.normal.x + 0.0,
                c.normal.y + 0.0, c.corner ? " (corner)" : "");
    ImGui::TextColored(colour(pal::kDim), "   touch (%.3f, %.3f)", c.touch.x, c.touch.y);
    ImGui::TextColored(colour(pal::kResponse), "   %s -> (%.3f, %.3f)",
                       responseText(w, c.response).c_str(), c.target.x, c.target.y);
  }
}

// A call as the game wrote it: the recording's names for the calls on a Mover and a Batch
// ("moverMove") are its own, not the library's.
std::string callWords(CallKind k) {
  switch (k) {
    case CallKind::moverMove:
      return "Mover::move";
    case CallKind::batchStep:
      return "Batch::step";
    default:
      return std::string(callKindName(k));
  }
}

}  // namespace

void recordingInspectorContents(const RecordingSession& s) {
  if (const auto& d = s.divergence()) {
    ImGui::TextColored(colour(pal::kBad), "DIVERGED at frame %" PRIu64 " call %u: %s", d->frame,
                       d->call, d->what.c_str());
    ImGui::TextColored(colour(pal::kBad), "  recorded %s, replayed %s", d->expected.c_str(),
                       d->got.c_str());
  }
  if (s.call()) {
    const CallInfo& c = s.calls()[*s.call()];
    ImGui::Text("call %u of frame %" PRIu64 ": %s", c.index, c.frame,
                callWords(c.kind).c_str());
    ImGui::TextWrapped("%s", c.summary.c_str());
    if (c.item.valid()) {
      const std::string cat = s.replay().category(c.item);
      ImGui::Text("item: %s%s%s", s.describe(c.item).c_str(), cat.empty() ? "" : "  category ",
                  cat.c_str());
    }
    if (const MoveTrace* m = s.callTrace()) {
      if (m->final != c.position) {
        ImGui::TextColored(colour(pal::kBad), "recorded end (%.3f, %.3f), replayed (%.3f, %.3f)",
                           c.position.x, c.position.y, m->final.x, m->final.y);
      }
      traceDetails(s, *m);
    } else if (c.kind == CallKind::queryRect || c.kind == CallKind::queryPoint ||
               c.kind == CallKind::querySegment || c.kind == CallKind::anyOverlap) {
      ImGui::TextColored(colour(pal::kDim), "%u results recorded (a query sweeps nothing)", c.hits);
    } else if (!s.traces(c)) {
      ImGui::TextColored(colour(pal::kDim), "nothing is swept by %s, so there is no trace",
                         callWords(c.kind).c_str());
    }
    return;
  }
  if (!s.selected()) {
    ImGui::TextColored(colour(pal::kDim),
                       "select a call (left), an item (Items) or click a body to trace it");
    return;
  }
  const ItemId id = *s.selected();
  const std::string cat = s.replay().category(id);
  ImGui::Text("%s%s%s", s.describe(id).c_str(), cat.empty() ? "" : "  category ", cat.c_str());
  if (s.world().has(id)) {
    const Rect r = s.world().rect(id);
    ImGui::Text("at (%.3f, %.3f)  size %g x %g", r.x, r.y, r.w, r.h);
  } else {
    ImGui::TextColored(colour(pal::kDim), "not in the world at this frame");
  }
  const auto moves = s.history();
  if (moves.empty()) {
    ImGui::TextColored(colour(pal::kDim), "no move of it in the last frames");
    return;
  }
  // Newest first: the move on screen is the one to read.
  for (std::size_t k = moves.size(); k-- > 0;) {
    const TracedMove& tm = moves[k];
    ImGui::PushID(static_cast<int>(k));
    const ImGuiTreeNodeFlags open = k + 1 == moves.size() ? ImGuiTreeNodeFlags_DefaultOpen : 0;
    if (ImGui::TreeNodeEx("move", open, "frame %" PRIu64 " move: %zu hits", tm.tick,
                          tm.trace.hits.size())) {
      traceDetails(s, tm.trace);
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
}

// [SECTION] HUD and layout -------------------------------------------------------------------

void recordingHudContents(const RecordingSession& s, const DebuggerState& st) {
  ImGui::Text("%s", s.name().c_str());
  ImGui::SameLine();
  ImGui::TextColored(colour(pal::kDim), "|");
  ImGui::SameLine();
  ImGui::Text("frame %" PRIu64 " (0..%" PRIu64 ")", s.frame(), s.lastFrame());
  ImGui::SameLine();
  ImGui::TextColored(colour(pal::kDim), "|");
  ImGui::SameLine();
  if (s.call()) {
    ImGui::Text("call %u of %zu", *s.call(), s.calls().size());
  } else {
    ImGui::Text("end of frame (%zu calls)", s.calls().size());
  }
  ImGui::SameLine();
  ImGui::TextColored(colour(pal::kDim), "|");
  ImGui::SameLine();
  ImGui::TextColored(colour(st.paused ? pal::kRender : pal::kGood),
                     st.paused ? "paused" : "playing");
  ImGui::TextColored(colour(pal::kDim), "traced: %s   %zu items   zoom %.2f px/unit",
                     s.selected() ? s.describe(*s.selected()).c_str() : "none", s.world().count(),
                     st.camera.scale());
  // A file cut short or with a bad chunk opens up to its last good frame: say so.
  for (const std::string& w : s.replay().warnings()) {
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 560.0f);
    ImGui::TextColored(colour(pal::kBad), "%s", w.c_str());
    ImGui::PopTextWrapPos();
  }
}

RecordingActions recordingLayout(RecordingSession& s, RecordingViewState& st, ImVec2 origin,
                                 ImVec2 display) {
  const float side = std::clamp(display.x * 0.36f, 340.0f, 500.0f);
  const float worldW = display.x - side;
  const float x0 = origin.x, y0 = origin.y;
  RecordingActions a;
  DebuggerState& view = st.view;

  if (beginCanvas("World", {x0, y0}, {worldW, display.y})) {
    if (auto pick = recordingWorldView("##world", s, view, {worldW, display.y})) a.item = *pick;
  }
  ImGui::End();

  ImGui::SetNextWindowBgAlpha(0.82f);
  ImGui::SetNextWindowPos({x0 + kMargin, y0 + kMargin}, ImGuiCond_Always);
  if (ImGui::Begin("HUD", nullptr, kOverlay | ImGuiWindowFlags_AlwaysAutoResize)) {
    recordingHudContents(s, view);
    view.coveredTop = ImGui::GetWindowPos().y - y0 + ImGui::GetWindowHeight() + kMargin;
  }
  ImGui::End();

  view.coveredBottom =
      detail::legendOverlay({x0, y0}, {worldW, display.y}, worldW > 700.0f ? 4 : 3,
                            s.pictureHasCategories());

  // The calls take the top third of the column; the inspector or the outliner the rest.
  const float callsH = std::floor(std::clamp(display.y * 0.34f, 120.0f, 260.0f));
  char title[96];
  std::snprintf(title, sizeof title, "Calls in frame %" PRIu64 " (%zu)###Calls", s.frame(),
                s.calls().size());
  place({x0 + worldW, y0}, {side, callsH});
  if (ImGui::Begin(title, nullptr, kFixed)) recordingCallsContents(s, st, a);
  ImGui::End();

  place({x0 + worldW, y0 + callsH}, {side, std::max(display.y - callsH, 60.0f)});
  if (ImGui::Begin("Details", nullptr, kFixed | ImGuiWindowFlags_NoTitleBar)) {
    if (ImGui::BeginTabBar("details")) {
      const auto flag = [&](int tab) {
        return st.showTab && *st.showTab == tab ? ImGuiTabItemFlags_SetSelected : 0;
      };
      if (ImGui::BeginTabItem("Inspector", nullptr, flag(0))) {
        ImGui::BeginChild("inspector");
        recordingInspectorContents(s);
        ImGui::EndChild();
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Items", nullptr, flag(1))) {
        recordingOutlinerContents(s, st, a);
        ImGui::EndTabItem();
      }
      st.showTab.reset();
      ImGui::EndTabBar();
    }
  }
  ImGui::End();
  return a;
}

}  // namespace tv::ui
