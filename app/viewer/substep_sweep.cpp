#include "substep_sweep.hpp"

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cmath>

#include "imgui.h"
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
    sim::Simulation exact(scene, params, parseMover("continuous"));
    exact_ = positionsAfter(exact, ticks_);
  } catch (const Error& e) {
    error_ = e.what();
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
    error_ = e.what();
  }
  points_.push_back(p);
  return true;
}

std::optional<double> SubstepSweep::draw(bool* open, double currentLength) {
  std::optional<double> picked;
  ImGui::SetNextWindowSize({430, 360}, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowPos({120, 120}, ImGuiCond_FirstUseEver);
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
  std::vector<float> tunnelled, error, ms;
  for (const SweepPoint& p : points_) {
    tunnelled.push_back(static_cast<float>(p.tunnelled));
    error.push_back(static_cast<float>(p.error));
    ms.push_back(static_cast<float>(p.msPerTick));
  }
  const auto n = static_cast<int>(lengths_.size());
  const float w = ImGui::GetContentRegionAvail().x;
  const auto plot = [&](const char* label, const std::vector<float>& v, const char* fmt) {
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, fmt, v.empty() ? 0.0 : static_cast<double>(v.back()));
    const float top = v.empty() ? 1.0f : std::max(*std::max_element(v.begin(), v.end()), 1e-6f);
    // Padded to the full count so the x axis is the same length in every plot.
    std::vector<float> padded = v;
    padded.resize(static_cast<std::size_t>(n), 0.0f);
    ImGui::PlotLines(label, padded.data(), static_cast<int>(v.size()), 0, overlay, 0.0f, top * 1.1f,
                     {w - 110.0f, 44.0f});
  };
  plot("tunnelled", tunnelled, "last %.0f");
  plot("error (px)", error, "last %.2f");
  plot("ms per tick", ms, "last %.3f");
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
      std::snprintf(label, sizeof label, "%g%s", p.length,
                    std::abs(p.length - currentLength) < 1e-9 ? "  (now)" : "");
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
