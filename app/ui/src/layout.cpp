#include "tv/ui/layout.hpp"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <initializer_list>

#include "tv/ui/palette.hpp"
#include "windows.hpp"

namespace tv::ui {

namespace pal = palette;

namespace {

using detail::beginCanvas;
using detail::kFixed;
using detail::kMargin;
using detail::kOverlay;
using detail::place;

struct Failure {
  const char* label;
  std::uint64_t sim::Counters::*field;
};
constexpr Failure kFailures[] = {
    {"escapes", &sim::Counters::escapes}, {"overlaps", &sim::Counters::overlaps},
    {"jitter", &sim::Counters::jitter},   {"snags", &sim::Counters::snags},
    {"misses", &sim::Counters::misses},
};


// Puts the next item on this line when `text` fits there, else on the next line.
void sameLineIfFits(const char* text) {
  ImGui::SameLine();
  if (ImGui::GetContentRegionAvail().x < ImGui::CalcTextSize(text).x) ImGui::NewLine();
}

// The first of `variants` (longest first) that fits the line; the last one otherwise, wrapped.
void textFitting(std::initializer_list<const char*> variants, ImU32 colour) {
  const float room = ImGui::GetContentRegionAvail().x;
  const char* chosen = *(variants.end() - 1);
  for (const char* v : variants) {
    if (ImGui::CalcTextSize(v).x <= room) {
      chosen = v;
      break;
    }
  }
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  ImGui::TextWrapped("%s", chosen);
  ImGui::PopStyleColor();
}

// A scale bar at the bottom right of the world view: a round length (1, 2 or 5 x 10^k px) that
// is 60..150 screen pixels long, so distances in the picture can be read without the HUD.
void drawScaleBar(ImDrawList& dl, const Camera& cam, float coveredBottom) {
  const double scale = cam.scale();
  if (!(scale > 0.0) || !std::isfinite(scale)) return;
  double length = std::pow(10.0, std::floor(std::log10(90.0 / scale)));
  for (const double m : {1.0, 2.0, 5.0, 10.0}) {
    if (length * m * scale >= 60.0) {
      length *= m;
      break;
    }
  }
  const float px = static_cast<float>(length * scale);
  const ImVec2 hi = cam.screenMax();
  const float y = hi.y - coveredBottom - 12.0f;
  const float x1 = hi.x - 14.0f, x0 = x1 - px;
  char text[32];
  std::snprintf(text, sizeof text, "%g px", length);
  const ImVec2 size = ImGui::CalcTextSize(text);
  dl.AddRectFilled({x0 - 6.0f, y - size.y - 6.0f}, {x1 + 6.0f, y + 6.0f}, IM_COL32(0, 0, 0, 150));
  dl.AddLine({x0, y}, {x1, y}, pal::kLabel, 2.0f);
  dl.AddLine({x0, y - 4.0f}, {x0, y + 4.0f}, pal::kLabel, 2.0f);
  dl.AddLine({x1, y - 4.0f}, {x1, y + 4.0f}, pal::kLabel, 2.0f);
  dl.AddText({(x0 + x1 - size.x) * 0.5f, y - size.y - 3.0f}, pal::kLabel, text);
}

}  // namespace

std::optional<std::size_t> worldView(const char* id, Session& session, DebuggerState& st,
                                     ImVec2 size) {
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
  std::optional<std::size_t> clicked;
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f) {
    st.camera.zoom(std::pow(1.2, static_cast<double>(io.MouseWheel)), io.MousePos);
    st.frameView.reset();
    st.cameraMoved = true;
  }
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Right)) {
    st.camera.pan(io.MouseDelta);
    st.frameView.reset();
    st.cameraMoved = true;
  }
  if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
    const Vec2 p = st.camera.toWorld(io.MousePos);
    const auto bodies = session.sim().bodies();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      if (contains(bodies[i].rect, p)) clicked = i;
    }
  }
  const WorldPicture pic = session.picture();
  ImDrawList& dl = *ImGui::GetWindowDrawList();
  drawWorld(dl, st.camera, pic, st.overlays);
  dl.PushClipRect(st.camera.screenMin(), st.camera.screenMax(), true);
  drawScaleBar(dl, st.camera, std::min(st.coveredBottom, size.y * 0.4f));
  dl.PopClipRect();
  return clicked;
}

Actions debuggerLayout(Session& session, DebuggerState& st, ImVec2 display) {
  return debuggerLayout(session, st, {0, 0}, display);
}

Actions debuggerLayout(Session& session, DebuggerState& st, ImVec2 origin, ImVec2 display) {
  // The column keeps the inspector's hit table readable; the world gets the rest.
  const float side = std::clamp(display.x * 0.35f, 340.0f, 480.0f);
  const float worldW = display.x - side;
  const float x0 = origin.x, y0 = origin.y;
  Actions a;

  if (beginCanvas("World", {x0, y0}, {worldW, display.y})) {
    if (auto pick = worldView("##world", session, st, {worldW, display.y})) a.select = pick;
  }
  ImGui::End();

  ImGui::SetNextWindowBgAlpha(0.82f);
  ImGui::SetNextWindowPos({x0 + kMargin, y0 + kMargin}, ImGuiCond_Always);
  if (ImGui::Begin("HUD", nullptr, kOverlay | ImGuiWindowFlags_AlwaysAutoResize)) {
    hudContents(session, st);
    st.coveredTop = ImGui::GetWindowPos().y - y0 + ImGui::GetWindowHeight() + kMargin;
  }
  ImGui::End();

  st.coveredBottom = detail::legendOverlay({x0, y0}, {worldW, display.y}, 4);

  float y = 0.0f;
  ImGui::SetNextWindowPos({x0 + worldW, y0 + y}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({side, 0}, ImGuiCond_Always);
  if (ImGui::Begin("Scene and mover", nullptr, kFixed)) {
    const Actions c = controlsContents(session, st);
    a.restart |= c.restart;
    a.step |= c.step;
    a.stepBack |= c.stepBack;
    a.togglePause |= c.togglePause;
    if (c.select) a.select = c.select;
    y += ImGui::GetWindowHeight();
  }
  ImGui::End();

  ImGui::SetNextWindowPos({x0 + worldW, y0 + y}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({side, 0}, ImGuiCond_Always);
  if (ImGui::Begin("Counters", nullptr, kFixed)) {
    countersContents(session);
    y += ImGui::GetWindowHeight();
  }
  ImGui::End();

  place({x0 + worldW, y0 + y}, {side, std::max(display.y - y, 60.0f)});
  if (ImGui::Begin("Inspector", nullptr, kFixed)) inspectorContents(session);
  ImGui::End();
  return a;
}

void comparisonLayout(std::span<Session* const> sessions, std::span<DebuggerState> states,
                      const std::string& title, ImVec2 display) {
  (void)comparisonLayout(sessions, states, title, {0, 0}, display);
}

std::optional<PanelPick> comparisonLayout(std::span<Session* const> sessions,
                                          std::span<DebuggerState> states, const std::string& title,
                                          ImVec2 origin, ImVec2 display, int legendColumns) {
  const std::size_t n = std::min(sessions.size(), states.size());
  if (n == 0) return std::nullopt;
  const float x0 = origin.x, y0 = origin.y;
  std::optional<PanelPick> picked;

  ImGui::SetNextWindowPos({x0, y0}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({display.x, 0}, ImGuiCond_Always);
  float top = 0.0f;
  // Before / after: the first panel failed where the last did not.
  const bool beforeAfter = n > 1 && failureCount(sessions[0]->sim().counters()) > 0 &&
                           failureCount(sessions[n - 1]->sim().counters()) == 0;
  if (ImGui::Begin("Title", nullptr, kOverlay)) {
    ImGui::TextWrapped("%s", title.c_str());  // a narrow window wraps it, never cuts it
    // The verdict, one coloured clause per mover: what a reader should take away.
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(pal::kDim), "verdict:");
    for (std::size_t k = 0; k < n; ++k) {
      const sim::Simulation& sim = sessions[k]->sim();
      const sim::Counters& c = sim.counters();
      std::string clause = sim.moverSpec().name() + ": ";
      char num[96];
      std::snprintf(num, sizeof num, "%" PRIu64 " of %zu tunnelled", c.tunnelled,
                    sim.bodies().size());
      clause += num;
      for (const auto& [label, field] : kFailures) {
        const bool used =
            std::any_of(sessions.begin(), sessions.begin() + static_cast<std::ptrdiff_t>(n),
                        [&](const Session* o) { return o->sim().counters().*field != 0; });
        if (!used) continue;
        std::snprintf(num, sizeof num, ", %s %" PRIu64, label, c.*field);
        clause += num;
      }
      // When it went wrong: the tick to step to.
      if (const auto first = sessions[k]->firstFailureTick(); first && failureCount(c) > 0) {
        std::snprintf(num, sizeof num, " (first at tick %" PRIu64 ")", *first);
        clause += num;
      }
      clause += k + 1 < n ? ";" : "";
      sameLineIfFits(clause.c_str());
      ImGui::TextColored(
          ImGui::ColorConvertU32ToFloat4(failureCount(c) > 0 ? pal::kBad : pal::kGood), "%s",
          clause.c_str());
    }
    top = ImGui::GetWindowHeight();
  }
  ImGui::End();

  ImGui::SetNextWindowPos({x0, y0 + display.y}, ImGuiCond_Always, {0, 1});
  ImGui::SetNextWindowSize({display.x, 0}, ImGuiCond_Always);
  float bottom = 0.0f;
  if (ImGui::Begin("Legend", nullptr, kOverlay)) {
    legendContents(legendColumns);
    bottom = ImGui::GetWindowHeight();
  }
  ImGui::End();

  const float w = std::floor(display.x / static_cast<float>(n));
  const float h = std::max(display.y - top - bottom, 100.0f);
  for (std::size_t k = 0; k < n; ++k) {
    Session& s = *sessions[k];
    DebuggerState& st = states[k];
    // Nothing covers a comparison's panels (title and legend sit outside them): a margin left
    // from the one-mover view would shrink every framing.
    st.coveredTop = st.coveredBottom = 0.0f;
    std::string name = s.sim().moverSpec().name();
    if (beforeAfter && k == 0) name = "before: " + name;
    if (beforeAfter && k + 1 == n) name = "after: " + name;
    // The id is the panel's place, so a title that changes (before/after) keeps the window.
    name += "###panel" + std::to_string(k);
    place({x0 + w * static_cast<float>(k), y0 + top}, {w, h});
    if (ImGui::Begin(name.c_str(), nullptr, kFixed | ImGuiWindowFlags_NoScrollbar)) {
      // Lines of numbers under the picture: the verdict, the traced move, the cost; a narrow
      // panel gets a line more, for the verdict's failure counts.
      const float lines = w < 420.0f ? 4.0f : 3.0f;
      const float stats = ImGui::GetTextLineHeightWithSpacing() * lines + 4.0f;
      const ImVec2 avail = ImGui::GetContentRegionAvail();
      if (auto pick = worldView("##world", s, st, {avail.x, std::max(avail.y - stats, 40.0f)})) {
        picked = PanelPick{k, *pick};
      }
      const sim::Counters& c = s.sim().counters();
      const std::size_t bodies = s.sim().bodies().size();
      char text[160];
      std::snprintf(text, sizeof text, "tunnelled so far: %" PRIu64 " of %zu", c.tunnelled, bodies);
      ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(c.tunnelled ? pal::kBad : pal::kGood), "%s",
                         text);
      // The scene's other failure counts, where any panel has one, so the columns line up.
      for (const auto& [label, field] : kFailures) {
        const bool used =
            std::any_of(sessions.begin(), sessions.begin() + static_cast<std::ptrdiff_t>(n),
                        [&](const Session* o) { return o->sim().counters().*field != 0; });
        if (!used) continue;
        std::snprintf(text, sizeof text, " %s %" PRIu64, label, c.*field);
        sameLineIfFits(text);
        ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(c.*field ? pal::kBad : pal::kGood), "%s",
                           text);
      }
      std::snprintf(text, sizeof text, "  hits %" PRIu64, c.hits);
      sameLineIfFits(text);
      ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(pal::kDim), "%s", text);
      const auto moves = s.moves();
      if (!moves.empty()) {
        const MoveTrace& m = moves.back().trace;
        char full[160], brief[160];
        std::snprintf(full, sizeof full, "tick %" PRIu64 " move: %zu cells, %zu candidates, %zu hits",
                      moves.back().tick, m.cells.size(), m.candidates.size(), m.hits.size());
        std::snprintf(brief, sizeof brief, "tick %" PRIu64 ": %zu cells, %zu cand., %zu hits",
                      moves.back().tick, m.cells.size(), m.candidates.size(), m.hits.size());
        textFitting({full, brief}, pal::kLabel);
      } else if (s.selected() && *s.selected() < bodies) {
        // Say why: a body that has stopped no longer moves, so there is no move to trace.
        textFitting({s.sim().bodies()[*s.selected()].active ? "no move traced yet"
                                                             : "no move traced: the body has stopped",
                     s.sim().bodies()[*s.selected()].active ? "no move yet" : "stopped: no move"},
                    pal::kDim);
      } else {
        textFitting({"no body traced"}, pal::kDim);
      }
      const sim::TraceStats& t = s.sim().traceStats();
      if (t.moves > 0) {
        const double mean = static_cast<double>(t.candidates) / static_cast<double>(t.moves);
        char full[160], brief[160];
        std::snprintf(full, sizeof full, "candidates per move: %.2f mean over %" PRIu64 " moves",
                      mean, t.moves);
        std::snprintf(brief, sizeof brief, "cand./move: %.2f (%" PRIu64 " moves)", mean, t.moves);
        textFitting({full, brief}, pal::kLabel);
      }
    }
    ImGui::End();
  }
  return picked;
}

namespace detail {

void place(ImVec2 pos, ImVec2 size, ImVec2 pivot) {
  ImGui::SetNextWindowPos(pos, ImGuiCond_Always, pivot);
  ImGui::SetNextWindowSize(size, ImGuiCond_Always);
}

bool beginCanvas(const char* name, ImVec2 pos, ImVec2 size) {
  place(pos, size);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {0, 0});
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  const bool open = ImGui::Begin(
      name, nullptr,
      kOverlay | ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse);
  ImGui::PopStyleVar(2);
  return open;
}

float legendOverlay(ImVec2 origin, ImVec2 size, int columns, bool withCategories) {
  ImGui::SetNextWindowBgAlpha(0.82f);
  place({origin.x + kMargin, origin.y + size.y - kMargin}, {size.x - 2 * kMargin, 0}, {0, 1});
  float covered = 0.0f;
  if (ImGui::Begin("Legend", nullptr, kOverlay)) {
    legendContents(columns, withCategories);
    covered = origin.y + size.y - ImGui::GetWindowPos().y + kMargin;
  }
  ImGui::End();
  return covered;
}

}  // namespace detail

}  // namespace tv::ui
