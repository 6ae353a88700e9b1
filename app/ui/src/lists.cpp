// The lists beside the world: the frame's calls, the items (outliner) and the failures.
#include <algorithm>
#include <cctype>
#include <cinttypes>
#include <cstdio>
#include <string>
#include <vector>

#include "tv/ui/palette.hpp"
#include "tv/ui/panels.hpp"

namespace tv::ui {

namespace pal = palette;

namespace {

ImVec4 colour(ImU32 c) {
  return ImGui::ColorConvertU32ToFloat4(c);
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

constexpr ImGuiTableFlags kTable = ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg |
                                   ImGuiTableFlags_SizingStretchProp |
                                   ImGuiTableFlags_BordersInnerV;

}  // namespace

// [SECTION] calls -------------------------------------------------------------------------------

void callsContents(const Source& s, bool& reveal, Actions& a) {
  const auto calls = s.calls();
  if (calls.empty()) {
    ImGui::TextColored(colour(pal::kDim), s.sim() ? "no body moved in this tick"
                                                  : "no calls in this frame");
    return;
  }
  const bool frameEnd = !s.call();
  const char* end = s.sim() ? "   end of tick (every body moved)" : "   end of frame (every call made)";
  if (ImGui::Selectable(end, frameEnd)) a.call = std::optional<std::uint32_t>{};
  const auto traced = s.traced();
  // A frame of a few hundred calls shows each whole, wrapped; a crowd's thousands one line each
  // (clipped to what is on screen), the whole line on hover.
  const bool wrapped = calls.size() <= 400;
  const float wrap = ImGui::GetContentRegionAvail().x;
  const auto row = [&](int i) {
    const CallInfo& c = calls[static_cast<std::size_t>(i)];
    const bool on = s.call() && *s.call() == static_cast<std::uint32_t>(i);
    const bool mine = traced && c.item.valid() && c.item == *traced;
    char text[320];
    std::snprintf(text, sizeof text, "%3d %s", i, c.summary.c_str());
    // The traced item's calls stand out; a move that hit something is red-tinted.
    ImU32 tint = mine ? pal::kLabel : pal::kDim;
    if (tracesAMove(c.kind) && c.hits > 0) tint = mine ? pal::kHit : IM_COL32(200, 120, 120, 255);
    ImGui::PushID(i);
    bool clicked = false;
    if (wrapped) {
      const ImVec2 at = ImGui::GetCursorScreenPos();
      const ImVec2 size = ImGui::CalcTextSize(text, nullptr, false, wrap);
      clicked = ImGui::Selectable("##call", on, 0, {0.0f, size.y});
      ImGui::GetWindowDrawList()->AddText(ImGui::GetFont(), ImGui::GetFontSize(), at, tint, text,
                                          nullptr, wrap);
    } else {
      ImGui::PushStyleColor(ImGuiCol_Text, tint);
      clicked = ImGui::Selectable(text, on);
      ImGui::PopStyleColor();
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", c.summary.c_str());
    }
    ImGui::PopID();
    if (clicked) a.call = on ? std::optional<std::uint32_t>{} : std::optional<std::uint32_t>(i);
    if (on && reveal) {
      ImGui::SetScrollHereY(0.5f);
      reveal = false;
    }
  };
  if (wrapped) {
    for (int i = 0; i < static_cast<int>(calls.size()); ++i) row(i);
    return;
  }
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(calls.size()));
  if (reveal && s.call())
    clipper.ForceDisplayRangeByIndices(static_cast<int>(*s.call()), static_cast<int>(*s.call()) + 1);
  while (clipper.Step()) {
    for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) row(i);
  }
}

// [SECTION] items -------------------------------------------------------------------------------

void itemsContents(const Source& s, OutlinerState& st, Actions& a) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "%s", st.filter.c_str());
  ImGui::SetNextItemWidth(-120.0f);
  if (st.focus) {
    ImGui::SetKeyboardFocusHere();
    st.focus = false;
  }
  if (ImGui::InputTextWithHint("##items", "search name or category", buffer, sizeof buffer)) {
    st.filter = buffer;
  }
  ImGui::SameLine();
  ImGui::Checkbox("moving only", &st.movingOnly);
  const std::string needle = lower(st.filter);
  std::vector<ItemRow> rows = s.items();
  const std::size_t all = rows.size();
  std::erase_if(rows, [&](const ItemRow& r) {
    if (st.movingOnly && !r.moves) return true;
    return !needle.empty() && lower(r.name + " " + r.category).find(needle) == std::string::npos;
  });
  // What moves first, by category: the player and the bullets together, the tiles after.
  std::stable_sort(rows.begin(), rows.end(), [](const ItemRow& x, const ItemRow& y) {
    if (x.moves != y.moves) return x.moves;
    if (x.category != y.category) return x.category < y.category;
    return x.moveCount > y.moveCount;
  });
  ImGui::TextColored(colour(pal::kDim), "%zu of %zu items", rows.size(), all);
  if (!ImGui::BeginTable("outliner", 4, kTable)) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthStretch, 3.0f);
  ImGui::TableSetupColumn("category", ImGuiTableColumnFlags_WidthStretch, 2.0f);
  ImGui::TableSetupColumn("moves", ImGuiTableColumnFlags_WidthStretch, 1.0f);
  ImGui::TableSetupColumn("hits", ImGuiTableColumnFlags_WidthStretch, 1.0f);
  ImGui::TableHeadersRow();
  const auto traced = s.traced();
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(rows.size()));
  while (clipper.Step()) {
    for (int r = clipper.DisplayStart; r < clipper.DisplayEnd; ++r) {
      const ItemRow& i = rows[static_cast<std::size_t>(r)];
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      const bool on = traced && *traced == i.id;
      ImGui::PushID(r);
      if (ImGui::Selectable(i.name.c_str(), on, ImGuiSelectableFlags_SpanAllColumns))
        a.item = on ? std::optional<ItemId>{} : std::optional<ItemId>(i.id);
      ImGui::PopID();
      if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("%s (%s): %ss %" PRIu64 "..%" PRIu64, i.name.c_str(),
                          i.category.empty() ? "no category" : i.category.c_str(), frameWord(s),
                          i.firstFrame, i.lastFrame);
      }
      ImGui::TableNextColumn();
      ImGui::TextColored(colour(pal::kDim), "%s", i.category.c_str());
      ImGui::TableNextColumn();
      // A source that does not count a body's moves (a scene) does not count its hits either:
      // both unknown, not 0.
      const bool counted = i.moveCount > 0 || !i.moves;
      if (counted) {
        ImGui::Text("%" PRIu64, i.moveCount);
      } else {
        ImGui::TextColored(colour(pal::kDim), "-");
      }
      ImGui::TableNextColumn();
      if (counted) {
        ImGui::Text("%" PRIu64, i.hits);
      } else {
        ImGui::TextColored(colour(pal::kDim), "-");
      }
    }
  }
  ImGui::EndTable();
}

// [SECTION] failures ----------------------------------------------------------------------------

void failuresContents(std::span<Source* const> panels, const FailureList& list,
                      std::optional<std::size_t> shown, bool& reveal, Actions& a) {
  if (!list.note.empty()) ImGui::TextColored(colour(pal::kDim), "%s", list.note.c_str());
  for (std::size_t p = 0; p < panels.size(); ++p) {
    std::size_t n = 0;
    for (const auto& e : list.entries) n += e.panel == p;
    const std::string who = panels[p]->moverName();
    ImGui::TextColored(colour(n > 0 ? pal::kBad : pal::kGood), "%s: %zu failed move%s%s",
                       who.c_str(), n, n == 1 ? "" : "s", list.complete ? "" : " so far");
    if (p < list.summary.size() && !list.summary[p].empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, pal::kDim);
      ImGui::Indent(12.0f);
      ImGui::TextWrapped("%s", list.summary[p].c_str());
      ImGui::Unindent(12.0f);
      ImGui::PopStyleColor();
    }
  }
  if (!list.complete) {
    ImGui::TextColored(colour(pal::kDim), "looking: %s %" PRIu64 "...",
                       panels.empty() ? "frame" : frameWord(*panels.front()), list.looked);
  }
  if (list.entries.empty()) return;
  // Wrapped: a narrow column (1024 px) cut it at "zoome".
  ImGui::PushStyleColor(ImGuiCol_Text, pal::kDim);
  ImGui::TextWrapped("click one: its %s, traced, centred and zoomed",
                     panels.empty() ? "frame" : frameWord(*panels.front()));
  ImGui::PopStyleColor();
  // Two lines a row: where and who, then what happened with the column's whole width. A few
  // thousand rows wrap what does not fit; more are drawn only where the list is scrolled to
  // (one fixed height), the whole text on hover.
  const bool several = panels.size() > 1;
  const char* word = panels.empty() ? "frame" : frameWord(*panels.front());
  ImGui::BeginChild("failure rows");
  const float wrap = ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x;
  const bool wrapped = list.entries.size() <= 2000;
  const float line = ImGui::GetTextLineHeight();
  const auto row = [&](int r) {
    const FailureList::Entry& e = list.entries[static_cast<std::size_t>(r)];
    const Source& s = *panels[std::min(e.panel, panels.size() - 1)];
    const std::string item = e.failure.item.valid() ? s.describe(e.failure.item) : "-";
    char head[192];
    if (e.failure.call) {
      std::snprintf(head, sizeof head, "%s %" PRIu64 " call %u   %s", word, e.failure.frame,
                    *e.failure.call, item.c_str());
    } else {
      std::snprintf(head, sizeof head, "%s %" PRIu64 "   %s", word, e.failure.frame, item.c_str());
    }
    const std::string who = several ? "   " + s.moverName() : std::string();
    // Measured as drawn below: indented, so wrapped 12 px sooner.
    const float whatH =
        wrapped ? ImGui::CalcTextSize(e.failure.what.c_str(), nullptr, false, wrap - 12.0f).y
                : line;
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImGui::PushID(r);
    const bool marked = shown && *shown == static_cast<std::size_t>(r);
    if (ImGui::Selectable("##failure", marked, 0, {0.0f, line + whatH + 2.0f}))
      a.failure = static_cast<std::size_t>(r);
    if (marked && reveal) ImGui::SetScrollHereY(0.3f);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("%s%s: %s", head, who.c_str(), e.failure.what.c_str());
    ImGui::PopID();
    ImDrawList& dl = *ImGui::GetWindowDrawList();
    dl.AddText(at, pal::kLabel, head);
    if (several) {
      dl.AddText({at.x + ImGui::CalcTextSize(head).x, at.y}, pal::kDim, who.c_str());
    }
    const ImU32 c = e.failure.kind == FailureKind::busy ? pal::kRender : pal::kBad;
    if (wrapped) {
      dl.AddText(ImGui::GetFont(), ImGui::GetFontSize(), {at.x + 12.0f, at.y + line + 1.0f}, c,
                 e.failure.what.c_str(), nullptr, wrap - 12.0f);
    } else {
      ImGui::PushClipRect(at, {at.x + wrap, at.y + 2.0f * line + 2.0f}, true);
      dl.AddText({at.x + 12.0f, at.y + line + 1.0f}, c, e.failure.what.c_str());
      ImGui::PopClipRect();
    }
  };
  if (wrapped) {
    for (int r = 0; r < static_cast<int>(list.entries.size()); ++r) row(r);
  } else {
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(list.entries.size()),
                  2.0f * line + 2.0f + ImGui::GetStyle().ItemSpacing.y);
    if (reveal && shown && *shown < list.entries.size()) {
      clipper.ForceDisplayRangeByIndices(static_cast<int>(*shown), static_cast<int>(*shown) + 1);
    }
    while (clipper.Step()) {
      for (int r = clipper.DisplayStart; r < clipper.DisplayEnd; ++r) row(r);
    }
  }
  reveal = false;
  ImGui::EndChild();
}

}  // namespace tv::ui
