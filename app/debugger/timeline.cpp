#include "timeline.hpp"

#include <algorithm>
#include <cinttypes>
#include <cmath>

#include "tv/ui/palette.hpp"

namespace tv::viewer {

namespace pal = ui::palette;

std::optional<std::uint64_t> timelineBar(const char* id, std::uint64_t current, std::uint64_t last,
                                         const TimelineMarks& marks, float width) {
  const float h = ImGui::GetFrameHeight();
  const ImVec2 p = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton(id, {std::max(width, 20.0f), h});
  const float w = std::max(width, 20.0f);
  const std::uint64_t first = std::min(marks.first, last);
  const double span = static_cast<double>(std::max<std::uint64_t>(last - first, 1));
  const auto xOf = [&](std::uint64_t t) {
    const double at = static_cast<double>(std::max(t, first) - first);
    return p.x + 4.0f + static_cast<float>(at / span) * (w - 8.0f);
  };
  const auto tickAt = [&](float x) {
    const double f = std::clamp(static_cast<double>((x - p.x - 4.0f) / (w - 8.0f)), 0.0, 1.0);
    return first + static_cast<std::uint64_t>(std::llround(f * span));
  };

  ImDrawList& dl = *ImGui::GetWindowDrawList();
  const ImVec2 q{p.x + w, p.y + h};
  dl.AddRectFilled(p, q, ImGui::GetColorU32(ImGuiCol_FrameBg));
  // What the look-ahead has covered, as a faint band: marks can only appear inside it.
  dl.AddRectFilled({p.x, q.y - 3.0f}, {xOf(std::min(marks.known, last)), q.y}, pal::kGridLine);
  // Decade ticks so a tick number can be found by eye.
  const double step = std::pow(10.0, std::floor(std::log10(std::max(span / 8.0, 1.0))));
  for (double t = 0.0; t <= span; t += step) {
    const float x = xOf(first + static_cast<std::uint64_t>(t));
    dl.AddLine({x, q.y - 6.0f}, {x, q.y}, pal::kDim);
  }
  // Every frame with a failure: a short red tick, so where things go wrong is seen at a glance.
  for (const std::uint64_t t : marks.failures) {
    if (t < first || t > last) continue;
    const float x = xOf(t);
    dl.AddLine({x, p.y + 1.0f}, {x, p.y + h * 0.45f}, (pal::kBad & 0x00FFFFFFu) | 0xB0000000u);
  }
  const auto mark = [&](std::optional<std::uint64_t> t, ImU32 colour) {
    if (!t || *t > last || *t < first) return;
    const float x = xOf(*t);
    dl.AddLine({x, p.y}, {x, q.y}, colour, 2.0f);
    dl.AddTriangleFilled({x - 5.0f, p.y}, {x + 5.0f, p.y}, {x, p.y + 6.0f}, colour);
  };
  mark(marks.difference, pal::kRender);
  mark(marks.implausible, IM_COL32(200, 120, 255, 255));
  mark(marks.failure, pal::kBad);
  mark(marks.diverged, pal::kBad);
  const float cx = xOf(std::min(current, last));
  dl.AddRectFilled({cx - 2.0f, p.y}, {cx + 2.0f, q.y}, pal::kSelected);

  std::optional<std::uint64_t> to;
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsItemActive() && (ImGui::IsItemActivated() || io.MouseDelta.x != 0.0f)) {
    to = tickAt(io.MousePos.x);
  }
  if (ImGui::IsItemHovered()) {
    const std::uint64_t t = tickAt(io.MousePos.x);
    ImGui::BeginTooltip();
    ImGui::Text("%s %" PRIu64, marks.unit, t);
    if (marks.failure) {
      ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(pal::kBad), "%s %" PRIu64 ": %s",
                         marks.unit, *marks.failure, marks.failureText.c_str());
    }
    if (marks.difference) {
      ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(pal::kRender),
                         "%s %" PRIu64 ": the movers' states first differ", marks.unit,
                         *marks.difference);
    }
    if (marks.diverged) {
      ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(pal::kBad), "DIVERGED at %s",
                         marks.divergedText.c_str());
    }
    ImGui::EndTooltip();
  }
  return to;
}

}  // namespace tv::viewer
