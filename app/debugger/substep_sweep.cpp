#include "substep_sweep.hpp"

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cmath>

#include "imgui.h"
#include "tv/app/user_message.hpp"
#include "tv/app/work_limit.hpp"
#include "tv/error.hpp"
#include "tv/sim/simulation.hpp"
#include "tv/ui/palette.hpp"

namespace tv::viewer {

namespace {

// Multiples of the tile: the article's tile / 2 in the middle, both failure ends around it.
constexpr double kFractions[] = {0.125, 0.25, 0.375, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0};

std::vector<Vec2> positionsAfter(sim::Simulation& s, std::uint64_t ticks) {
  while (s.ticks() < ticks) s.tick();
  std::vector<Vec2> out;
  for (const sim::Body& b : s.bodies()) out.push_back(b.rect.position());
  return out;
}

}  // namespace

bool SubstepSweep::stale(const sim::SceneDef& scene, const sim::Params& params,
                         const MoverSpec& mover, std::uint64_t ticks) const {
  const bool substep = mover.kind == MoverKind::substep;
  const MoverKind inner = substep ? mover.inner : MoverKind::discrete;
  // The substep parameter itself is what the sweep varies, so it is left out of the compare.
  bool sameParams = params.specs().size() == params_.specs().size();
  for (std::size_t i = 0; sameParams && i < params.values().size(); ++i) {
    if (params.specs()[i].name == sim::param::substep) continue;
    sameParams = params.values()[i] == params_.values()[i];
  }
  return scene_ != &scene || !sameParams || inner != mover_.inner || ticks != ticks_;
}

void SubstepSweep::reset(const sim::SceneDef& scene, const sim::Params& params, MoverSpec mover,
                         std::uint64_t ticks) {
  scene_ = &scene;
  params_ = params;
  mover_ = MoverSpec{};
  mover_.kind = MoverKind::substep;
  mover_.inner = mover.kind == MoverKind::substep ? mover.inner : MoverKind::discrete;
  ticks_ = std::max<std::uint64_t>(ticks, 1);
  points_.clear();
  lengths_.clear();
  exact_.clear();
  error_.clear();
  const double tile = params.get(sim::param::tile);
  for (const double f : kFractions) lengths_.push_back(tile * f);
  try {
    sim::Simulation exact(scene, params, MoverSpec{.kind = MoverKind::continuous});
    exact_ = positionsAfter(exact, ticks_);
  } catch (const Error& e) {
    error_ = app::userMessage(e);
    lengths_.clear();
  }
}

bool SubstepSweep::advance() {
  if (!scene_ || points_.size() >= lengths_.size()) return false;
  SweepPoint p;
  p.length = lengths_[points_.size()];
  try {
    sim::Params params = params_;
    params.set(sim::param::substep, p.length);
    sim::Simulation s(*scene_, params, mover_);
    // A length that cuts the moves into millions of pieces would freeze the window: skipped.
    if (app::workLimitExceeded(params, s.moverSpec(), s.bodies().size())) {
      p.skipped = true;
      points_.push_back(p);
      return true;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<Vec2> at = positionsAfter(s, ticks_);
    const std::chrono::duration<double, std::milli> spent = std::chrono::steady_clock::now() - t0;
    p.msPerTick = spent.count() / static_cast<double>(ticks_);
    p.tunnelled = s.counters().tunnelled;
    double sum = 0.0;
    for (std::size_t i = 0; i < at.size() && i < exact_.size(); ++i) {
      sum += std::hypot(at[i].x - exact_[i].x, at[i].y - exact_[i].y);
    }
    p.error = at.empty() ? 0.0 : sum / static_cast<double>(at.size());
  } catch (const Error& e) {
    error_ = app::userMessage(e);
  }
  points_.push_back(p);
  return true;
}

std::optional<double> SubstepSweep::draw(bool* open, double currentLength, bool byDefault) {
  std::optional<double> picked;
  // Clear of the toolbar and status line below at 640 px tall too.
  const float room = ImGui::GetMainViewport()->Size.y - 190.0f;
  ImGui::SetNextWindowSize({430, room < 520.0f ? (room > 200.0f ? room : 200.0f) : 520.0f},
                           ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowPos({120, 120}, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(1.0f);  // over the panels: their labels must not show through
  if (!ImGui::Begin("Substep sweep (T)", open)) {
    ImGui::End();
    return picked;
  }
  ImGui::TextWrapped("%s, ticks 0..%" PRIu64
                     ", max substep length from tile/8 to 4 tiles. "
                     "Click a row to use that length.",
                     mover_.name().c_str(), ticks_);
  if (!error_.empty()) {
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(ui::palette::kBad), "%s", error_.c_str());
  }
  // Three small plots against the substep length, each with its axes: the length (px, log, as
  // the lengths are multiples of the tile) along the bottom and the measure's unit at the left.
  std::vector<double> xs, tunnelled, error, ms;
  for (const SweepPoint& p : points_) {
    if (p.skipped) continue;
    xs.push_back(p.length);
    tunnelled.push_back(static_cast<double>(p.tunnelled));
    error.push_back(p.error);
    ms.push_back(p.msPerTick);
  }
  const double xLo = lengths_.empty() ? 1.0 : lengths_.front();
  const double xHi = lengths_.empty() ? 2.0 : std::max(lengths_.back(), xLo * 1.001);
  const auto plot = [&](const char* title, const char* unit, const std::vector<double>& v,
                        const char* fmt) {
    ImDrawList& dl = *ImGui::GetWindowDrawList();
    const ImGuiStyle& style = ImGui::GetStyle();
    const float line = ImGui::GetTextLineHeight();
    const float axisW = ImGui::CalcTextSize("00000.0").x + 4.0f;
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float w = ImGui::GetContentRegionAvail().x, h = 46.0f;
    const ImVec2 lo{at.x + axisW, at.y + line}, hi{at.x + w - 4.0f, at.y + line + h};
    ImGui::Dummy({w, line + h + line + style.ItemSpacing.y});
    const ImU32 ink = ImGui::GetColorU32(ImGuiCol_Text);
    const ImU32 dim = ui::palette::kDim;
    char text[64];
    std::snprintf(text, sizeof text, "%s (%s)", title, unit);
    dl.AddText({at.x, at.y}, ink, text);
    dl.AddRectFilled(lo, hi, ImGui::GetColorU32(ImGuiCol_FrameBg));
    const double top = v.empty() ? 1.0 : std::max(*std::max_element(v.begin(), v.end()), 1e-9);
    // The y axis: 0 and the largest value, in the measure's unit.
    std::snprintf(text, sizeof text, fmt, top);
    dl.AddText({lo.x - ImGui::CalcTextSize(text).x - 3.0f, lo.y - 1.0f}, dim, text);
    std::snprintf(text, sizeof text, fmt, 0.0);
    dl.AddText({lo.x - ImGui::CalcTextSize(text).x - 3.0f, hi.y - line}, dim, text);
    const auto sx = [&](double x) {
      return lo.x + static_cast<float>(std::log(x / xLo) / std::log(xHi / xLo)) * (hi.x - lo.x);
    };
    const auto sy = [&](double y) {
      return hi.y - static_cast<float>(y / (top * 1.1)) * (hi.y - lo.y);
    };
    // The x axis: a tick at every length run, a label where it fits (px).
    float lastLabel = -1e9f;
    for (const double x : lengths_) {
      const float X = sx(x);
      dl.AddLine({X, hi.y}, {X, hi.y + 3.0f}, dim);
      std::snprintf(text, sizeof text, "%g", x);
      const float tw = ImGui::CalcTextSize(text).x;
      if (X - tw * 0.5f > lastLabel + 6.0f && X + tw * 0.5f <= at.x + w) {
        dl.AddText({X - tw * 0.5f, hi.y + 3.0f}, dim, text);
        lastLabel = X + tw * 0.5f;
      }
    }
    for (std::size_t i = 0; i + 1 < v.size(); ++i)
      dl.AddLine({sx(xs[i]), sy(v[i])}, {sx(xs[i + 1]), sy(v[i + 1])}, ink, 1.5f);
    for (std::size_t i = 0; i < v.size(); ++i) dl.AddCircleFilled({sx(xs[i]), sy(v[i])}, 2.5f, ink);
    // Where the scene runs now.
    if (currentLength >= xLo && currentLength <= xHi) {
      const float X = sx(currentLength);
      dl.AddLine({X, lo.y}, {X, hi.y}, ui::palette::kRender, 1.0f);
    }
  };
  plot("tunnelled", "bodies", tunnelled, "%.0f");
  plot("error", "px", error, "%.2f");
  plot("time", "ms per tick", ms, "%.3f");
  ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(ui::palette::kDim),
                     "x: max substep length (px, log); orange: the length now");
  // The parameter reads 0 when the length is the default: say what that comes to, as the
  // panel's field does.
  ImGui::TextWrapped("the length now: %g px%s", currentLength,
                     byDefault ? " (the substep parameter is 0: tile/2)" : "");
  if (ImGui::BeginTable(
          "sweep", 4,
          ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_ScrollY)) {
    ImGui::TableSetupColumn("substep (px)");
    ImGui::TableSetupColumn("tunnelled");
    ImGui::TableSetupColumn("error (px)");
    ImGui::TableSetupColumn("ms / tick");
    ImGui::TableHeadersRow();
    for (const SweepPoint& p : points_) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      char label[32];
      const bool now = std::abs(p.length - currentLength) < 1e-9;
      std::snprintf(label, sizeof label, "%g%s", p.length, now ? "  (now)" : "");
      if (ImGui::Selectable(label, std::abs(p.length - currentLength) < 1e-9,
                            ImGuiSelectableFlags_SpanAllColumns)) {
        picked = p.length;
      }
      ImGui::TableNextColumn();
      if (p.skipped) {
        ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(ui::palette::kDim),
                           "skipped: over %g s a tick", app::kMaxSecondsPerTick);
        continue;
      }
      ImGui::TextColored(
          ImGui::ColorConvertU32ToFloat4(p.tunnelled ? ui::palette::kBad : ui::palette::kGood),
          "%" PRIu64, p.tunnelled);
      ImGui::TableNextColumn();
      ImGui::Text("%.3f", p.error);
      ImGui::TableNextColumn();
      ImGui::Text("%.3f", p.msPerTick);
    }
    if (pending() > 0) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(ui::palette::kDim), "running %zu more...",
                         pending());
    }
    ImGui::EndTable();
  }
  ImGui::End();
  return picked;
}

}  // namespace tv::viewer
