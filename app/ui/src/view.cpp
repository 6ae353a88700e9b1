// The view: world panels, HUD or title, legend and the column, for every source.
//
// [SECTION] the world view
// [SECTION] verdicts
// [SECTION] one panel
// [SECTION] several panels: side by side, overlaid
// [SECTION] the column
// [SECTION] the view
#include "tv/ui/view.hpp"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <initializer_list>

#include "draw_util.hpp"
#include "tv/error.hpp"
#include "tv/ui/palette.hpp"
#include "tv/ui/replay_source.hpp"
#include "tv/ui/sim_source.hpp"
#include "tv/ui/words.hpp"
#include "windows.hpp"

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

// Puts the next item on this line when `text` fits there, else on the next line.
void sameLineIfFits(const char* text) {
  ImGui::SameLine();
  if (ImGui::GetContentRegionAvail().x < ImGui::CalcTextSize(text).x) ImGui::NewLine();
}

// The first of `variants` (longest first) that fits the line; the last one otherwise, wrapped.
void textFitting(std::initializer_list<const char*> variants, ImU32 c) {
  const float room = ImGui::GetContentRegionAvail().x;
  const char* chosen = *(variants.end() - 1);
  for (const char* v : variants) {
    if (ImGui::CalcTextSize(v).x <= room) {
      chosen = v;
      break;
    }
  }
  ImGui::PushStyleColor(ImGuiCol_Text, c);
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

// The move's failure: the source's own, else the Failures list's.
std::optional<Failure> failureFor(const Source& s, const TracedMove& m, const FailureList* list,
                                  std::size_t panel) {
  if (auto f = s.failureOf(m)) return f;
  if (!list) return std::nullopt;
  for (const FailureList::Entry& e : list->entries) {
    if (e.panel == panel && e.failure.frame == m.tick && e.failure.item == m.trace.item)
      return e.failure;
  }
  return std::nullopt;
}

// What happened to the traced move, said under where it ended.
void sayWhatHappened(ImDrawList& dl, const Camera& cam, float coveredBottom, const Source& s,
                     const FailureList* list, std::size_t panel) {
  const auto moves = s.history();
  if (moves.empty()) return;
  const TracedMove& last = moves.back();
  // Only the move of the frame on screen: an older one is history, not what just happened.
  if (last.tick != s.frame()) return;
  const MoveTrace* callTrace = s.callTrace();
  if (s.call() && !callTrace) return;
  const MoveTrace& m = callTrace ? *callTrace : last.trace;
  const auto failed = failureFor(s, last, list, panel);
  const Said said = whatHappened(m, s, failed ? &*failed : nullptr);
  if (said.text.empty()) return;
  // Above the move, over its "start" and "goal" labels (which stack when they are close, see
  // drawMove): the hit labels go beside and below it.
  const Rect hull = unite(m.start, m.start.at(m.final));
  if (!cam.sees(hull)) return;
  const ImVec2 s0 = cam.toScreenMin(m.start), g0 = cam.toScreenMin(m.start.at(m.goal));
  const float width = ImGui::CalcTextSize("start").x + 8.0f;
  const bool stacked = !(g0.x == s0.x && g0.y == s0.y) && std::abs(g0.x - s0.x) < width &&
                       std::abs(g0.y - s0.y) < 16.0f;
  const float top = std::min({s0.y, g0.y, cam.toScreenMin(hull).y});
  // The whole when it fits the view, else its first clause (the inspector has the whole).
  // The room is the panel's, as drawn (its clip rect), which may be narrower than the camera's
  // view: measured on the camera alone, "pushed back out of floor tile 2" lost its "2".
  const float room = std::min(cam.screenMax().x - cam.screenMin().x - 16.0f,
                              dl.GetClipRectMax().x - dl.GetClipRectMin().x - 8.0f);
  const std::string& text = ImGui::CalcTextSize(said.text.c_str()).x <= room ? said.text : said.brief;
  const ImVec2 at{cam.toScreenMin(hull).x, top - (stacked ? 45.0f : 31.0f)};
  const ImU32 c = said.bad ? pal::kBad : pal::kGood;
  if (ImGui::CalcTextSize(text.c_str()).x <= room) {
    detail::label(dl, at, c, text);
  } else {
    // Even the first clause is wider than a narrow panel: on two lines, never cut.
    detail::labelWrapped(dl, at, c, text, room);
  }
  (void)coveredBottom;
}

}  // namespace

void syncPanels(ViewState& v, const Session& s) {
  if (v.panels.empty()) v.panels.emplace_back();
  // A copy: push_back below may move the panels, and a reference to the first with them.
  const DebuggerState first = v.panels.front();
  while (v.panels.size() < s.size()) {
    DebuggerState p;
    p.overlays = first.overlays;
    p.camera = first.camera;
    p.frameView = first.frameView ? first.frameView : std::optional<Rect>(first.camera.view());
    p.paused = first.paused;
    v.panels.push_back(p);
  }
  v.panels.resize(s.size());
  v.inspected = std::min(v.inspected, s.size() - 1);
}

// [SECTION] the world view ------------------------------------------------------------------------

std::optional<ItemId> worldView(const char* id, Source& source, DebuggerState& st, ImVec2 size,
                                const FailureList* failures, std::size_t panel) {
  const ImVec2 pos = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton(id, size,
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  if (st.frameView) {
    const float top = std::min(st.coveredTop, size.y * 0.4f);
    const float bottom = std::min(st.coveredBottom, size.y * 0.4f);
    st.camera.frame(*st.frameView, pos, size, {pos.x, pos.y + top}, {size.x, size.y - top - bottom});
  } else {
    st.camera.place(pos, size);
  }
  std::optional<ItemId> clicked;
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
    clicked = source.itemAt(st.camera.toWorld(io.MousePos));
  }
  if (ImGui::IsItemHovered() && !ImGui::IsMouseDown(ImGuiMouseButton_Right)) {
    if (const auto under = source.itemAt(st.camera.toWorld(io.MousePos))) {
      const std::string cat = source.category(*under);
      // "bullet 4 (bullet): click to trace"; the category only where it says more than the name.
      const std::string name = source.describe(*under);
      const bool says = !cat.empty() && name.rfind(cat, 0) != 0;
      ImGui::SetTooltip("%s%s%s%s: click to trace", name.c_str(), says ? " (" : "",
                        says ? cat.c_str() : "", says ? ")" : "");
    }
  }
  const WorldPicture pic = source.picture();
  ImDrawList& dl = *ImGui::GetWindowDrawList();
  drawWorld(dl, st.camera, pic, st.overlays);
  dl.PushClipRect(st.camera.screenMin(), st.camera.screenMax(), true);
  if (st.overlays.labels)
    sayWhatHappened(dl, st.camera, std::min(st.coveredBottom, size.y * 0.4f), source, failures, panel);
  drawScaleBar(dl, st.camera, std::min(st.coveredBottom, size.y * 0.4f));
  dl.PopClipRect();
  return clicked;
}

// [SECTION] verdicts ------------------------------------------------------------------------------

namespace {

struct Count {
  const char* label;
  std::uint64_t sim::Counters::*field;
};
constexpr Count kCounts[] = {
    {"escapes", &sim::Counters::escapes},
    {"overlaps", &sim::Counters::overlaps},
    {"jitter", &sim::Counters::jitter},
};

bool anyPanel(std::span<Source* const> all, std::uint64_t sim::Counters::*field) {
  return std::any_of(all.begin(), all.end(), [&](const Source* s) {
    return s->sim() && s->sim()->simulation().counters().*field != 0;
  });
}

std::size_t countRole(const sim::Simulation& s, std::initializer_list<sim::BodyRole> roles) {
  std::size_t n = 0;
  for (const sim::Body& b : s.bodies()) {
    n += std::find(roles.begin(), roles.end(), b.role) != roles.end();
  }
  return n;
}

}  // namespace

Verdict verdictOf(const SimSource& source, std::span<Source* const> all, bool withMover) {
  const sim::Simulation& sim = source.simulation();
  const sim::Counters& c = sim.counters();
  const sim::SceneDef& scene = sim.scene();
  Verdict v;
  std::string& t = v.text;
  if (withMover) t = sim.moverSpec().name() + ": ";
  char num[128];
  // A world where nothing can meet anything (no solid, and no body that collides with another
  // body) cannot fail: say that, not a green "0 tunnelled".
  std::uint32_t layers = 0, masks = 0;
  for (const sim::Body& b : sim.bodies()) {
    layers |= b.layer;
    masks |= b.mask;
  }
  if (sim.solids().empty() && (masks & layers) == 0) {
    t += "nothing is solid here, so nothing can fail";
    v.neutral = true;
    return v;
  }
  // Tunnelling scenes count their projectiles; walking scenes their snags.
  const std::size_t shots = countRole(sim, {sim::BodyRole::projectile});
  const bool walking = countRole(sim, {sim::BodyRole::walker, sim::BodyRole::player}) > 0;
  std::vector<std::string> clauses;
  if (shots > 0) {
    std::snprintf(num, sizeof num, "%" PRIu64 " of %zu projectile%s tunnelled", c.tunnelled, shots,
                  shots == 1 ? "" : "s");
    clauses.emplace_back(num);
  } else if (c.tunnelled > 0 || anyPanel(all, &sim::Counters::tunnelled)) {
    std::snprintf(num, sizeof num, "tunnelled %" PRIu64, c.tunnelled);
    clauses.emplace_back(num);
  }
  if (walking || anyPanel(all, &sim::Counters::snags)) {
    std::snprintf(num, sizeof num, "snags %" PRIu64, c.snags);
    clauses.emplace_back(num);
  }
  for (const auto& [label, field] : kCounts) {
    if (!anyPanel(all, field)) continue;
    std::snprintf(num, sizeof num, "%s %" PRIu64, label, c.*field);
    clauses.emplace_back(num);
  }
  if (anyPanel(all, &sim::Counters::misses)) {
    std::snprintf(num, sizeof num, "%s %" PRIu64, scene.missesWord.c_str(), c.misses);
    clauses.emplace_back(num);
  }
  // Scenes of moving solids: riders dropped or popped are failures; squishes are what a solid
  // pressing a body against a wall should report, counted but not against the mover.
  const auto bodies = sim.bodies();
  const bool solids = std::any_of(bodies.begin(), bodies.end(), [](const sim::Body& b) {
    return b.solid || b.layer == sim::kLayerSolid;
  });
  if (solids || anyPanel(all, &sim::Counters::drops) || anyPanel(all, &sim::Counters::pops)) {
    std::snprintf(num, sizeof num, "drops %" PRIu64 ", pops %" PRIu64, c.drops, c.pops);
    clauses.emplace_back(num);
  }
  if (c.squishes > 0 || anyPanel(all, &sim::Counters::squishes)) {
    std::snprintf(num, sizeof num, "squished %" PRIu64, c.squishes);
    clauses.emplace_back(num);
  }
  if (clauses.empty()) {
    std::snprintf(num, sizeof num, "nothing failed in %" PRIu64 " moves", c.moves);
    clauses.emplace_back(num);
  }
  for (std::size_t k = 0; k < clauses.size(); ++k) t += (k ? ", " : "") + clauses[k];
  const bool missed = scene.missesFail && c.misses > 0;
  v.bad = failureCount(c) > 0 || missed;
  // When it went wrong: the tick to step to.
  if (const auto first = source.firstFailureTick(); first && failureCount(c) > 0) {
    std::snprintf(num, sizeof num, " (first at tick %" PRIu64 ")", *first);
    t += num;
  }
  return v;
}

// [SECTION] one panel -----------------------------------------------------------------------------

namespace {

struct Column {
  float x = 0.0f, y = 0.0f, w = 0.0f, h = 0.0f;
};

void drawColumn(Session& s, ViewState& v, const Column& c, Actions& a);

void onePanel(Session& s, ViewState& v, ImVec2 origin, ImVec2 size, float side, Actions& a) {
  const float worldW = size.x - side;
  Source& src = s.primary();
  DebuggerState& st = v.panels.front();
  if (beginCanvas("World", origin, {worldW, size.y})) {
    if (auto pick = worldView("##world", src, st, {worldW, size.y}, &v.failures, 0))
      a.item = pick;
  }
  ImGui::End();

  ImGui::SetNextWindowBgAlpha(0.82f);
  ImGui::SetNextWindowPos({origin.x + kMargin, origin.y + kMargin}, ImGuiCond_Always);
  if (ImGui::Begin("HUD", nullptr, kOverlay | ImGuiWindowFlags_AlwaysAutoResize)) {
    hudContents(src, st);
    if (const SimSource* sim = src.sim()) {
      Source* self = &src;
      const Verdict verdict = verdictOf(*sim, {&self, 1}, false);
      ImGui::TextColored(colour(verdict.neutral ? pal::kRender
                                                : (verdict.bad ? pal::kBad : pal::kGood)),
                         "%s", verdict.text.c_str());
    }
    st.coveredTop = ImGui::GetWindowPos().y - origin.y + ImGui::GetWindowHeight() + kMargin;
  }
  ImGui::End();
  const palette::LegendScope scope = legendScopeOf(src);
  st.coveredBottom = detail::legendOverlay(
      origin, {worldW, size.y},
      std::min(worldW > 700.0f ? 4 : 3, legendColumns(worldW - 2 * kMargin, scope)), scope);
  drawColumn(s, v, {origin.x + worldW, origin.y, side, size.y}, a);
}

// [SECTION] several panels: side by side, overlaid ------------------------------------------------

std::string compareTitle(Session& s, const ViewState& v) {
  Source& first = s.primary();
  char text[512];
  const auto traced = first.traced();
  const std::string tracedName = traced ? first.describe(*traced) : "none";
  if (const SimSource* sim = first.sim()) {
    const sim::Params& p = sim->simulation().params();
    std::snprintf(text, sizeof text,
                  "%s at tick %" PRIu64
                  "   |   speed %g px/s, size %g px, tile %g px, dt %.2f ms, max substep %s   |   "
                  "traced: %s",
                  first.name().c_str(), first.frame(), p.get(sim::param::speed),
                  p.get(sim::param::size), p.get(sim::param::tile), p.get(sim::param::dt) * 1000.0,
                  p.get(sim::param::substep) == 0.0
                      ? "tile/2"
                      : (formatNumber(p.get(sim::param::substep)) + " px").c_str(),
                  tracedName.c_str());
  } else {
    std::string others;
    for (std::size_t k = 1; k < s.size(); ++k)
      others += (k > 1 ? ", " : "") + s.panel(k).moverName();
    std::snprintf(text, sizeof text,
                  "%s   frame %" PRIu64 "   |   the %s run beside a re-run by %s   |   traced: %s",
                  first.name().c_str(), first.frame(), first.moverName().c_str(), others.c_str(),
                  tracedName.c_str());
  }
  std::string title = text;
  if (!v.caption.empty()) title += "\n" + v.caption;
  return title;
}

// Lines of numbers under a panel's picture: the verdict, the traced move, the cost.
void panelStats(Session& s, std::size_t k, float w) {
  Source& src = s.panel(k);
  const auto all = s.panels();
  if (const SimSource* sim = src.sim()) {
    const Verdict verdict = verdictOf(*sim, all, false);
    textFitting({verdict.text.c_str()},
                verdict.neutral ? pal::kRender : (verdict.bad ? pal::kBad : pal::kGood));
    (void)w;
  }
  const auto moves = src.history();
  const MoveTrace* m = src.callTrace();
  if (!m && !moves.empty()) m = &moves.back().trace;
  if (m) {
    char full[200], brief[160];
    std::snprintf(full, sizeof full, "%s %" PRIu64 " move: %zu cells, %zu candidates, %zu hits",
                  frameWord(src), moves.empty() ? src.frame() : moves.back().tick, m->cells.size(),
                  m->candidates.size(), m->hits.size());
    std::snprintf(brief, sizeof brief, "%zu cells, %zu cand., %zu hits", m->cells.size(),
                  m->candidates.size(), m->hits.size());
    textFitting({full, brief}, pal::kLabel);
    if (k > 0 && src.openLoop()) {
      // How far the re-run ended from where the recorded run did.
      const MoveTrace* r = s.primary().callTrace();
      const auto rm = s.primary().history();
      if (!r && !rm.empty()) r = &rm.back().trace;
      if (r) {
        const double d = std::hypot(m->final.x - r->final.x, m->final.y - r->final.y);
        char text[96];
        std::snprintf(text, sizeof text, d > 0.0 ? "%.3f from the recorded end" : "same end as recorded", d);
        textFitting({text}, d > 0.0 ? pal::kRender : pal::kGood);
      }
    }
  } else if (const auto id = src.traced()) {
    const SimSource* sim = src.sim();
    const auto b = sim ? sim->bodyOf(*id) : std::nullopt;
    if (b && !sim->simulation().bodies()[*b].active) {
      textFitting({"no move traced: the body has stopped", "stopped: no move"}, pal::kDim);
    } else if (b && sim->simulation().bodies()[*b].solid) {
      textFitting({"a moving solid: its moves are not traced", "not traced"}, pal::kDim);
    } else if (b && sim->simulation().bodies()[*b].maxNudge > 0.0) {
      textFitting({"moved with corner correction: not traced, nudges drawn", "not traced"},
                  pal::kDim);
    } else if (!src.world().has(*id)) {
      // A recorded item removed (a bullet that hit), or not added yet.
      const std::string gone = src.describe(*id) + " is not in the world at this " + frameWord(src);
      textFitting({gone.c_str(), "not in the world"}, pal::kDim);
    } else {
      textFitting({"no move of it traced yet", "no move yet"}, pal::kDim);
    }
  } else {
    textFitting({"nothing traced"}, pal::kDim);
  }
  if (const SimSource* sim = src.sim()) {
    const sim::TraceStats& t = sim->simulation().traceStats();
    if (t.moves > 0) {
      const double mean = static_cast<double>(t.candidates) / static_cast<double>(t.moves);
      char full[160], brief[160];
      std::snprintf(full, sizeof full, "candidates per move: %.2f mean over %" PRIu64 " moves", mean,
                    t.moves);
      std::snprintf(brief, sizeof brief, "cand./move: %.2f (%" PRIu64 " moves)", mean, t.moves);
      textFitting({full, brief}, pal::kLabel);
    }
  }
}

void sideBySide(Session& s, ViewState& v, ImVec2 origin, ImVec2 size, float side, Actions& a) {
  const std::size_t n = s.size();
  const float panelsW = size.x - side;
  const float x0 = origin.x, y0 = origin.y;
  ImGui::SetNextWindowPos({x0, y0}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({panelsW, 0}, ImGuiCond_Always);
  float top = 0.0f;
  const bool whatIf = s.whatIf();
  // Before / after: the first panel failed where the last did not.
  const SimSource* firstSim = s.primary().sim();
  const SimSource* lastSim = s.panel(n - 1).sim();
  const bool beforeAfter = firstSim && lastSim &&
                           failureCount(firstSim->simulation().counters()) > 0 &&
                           failureCount(lastSim->simulation().counters()) == 0;
  const auto all = s.panels();
  if (ImGui::Begin("Title", nullptr, kOverlay)) {
    ImGui::TextWrapped("%s", compareTitle(s, v).c_str());  // a narrow window wraps it, never cuts
    if (whatIf) {
      ImGui::PushStyleColor(ImGuiCol_Text, pal::kRender);
      ImGui::TextWrapped(
          "Open-loop: the game's recorded goals are replayed as they were; how the game would "
          "have reacted to a different outcome is not in the file.");
      ImGui::PopStyleColor();
    } else if (firstSim) {
      // The verdict, one coloured clause per mover: what a reader should take away.
      ImGui::TextColored(colour(pal::kDim), "verdict:");
      for (std::size_t k = 0; k < n; ++k) {
        const SimSource* sim = s.panel(k).sim();
        if (!sim) continue;
        Verdict verdict = verdictOf(*sim, all, true);
        if (k + 1 < n) verdict.text += ";";
        sameLineIfFits(verdict.text.c_str());
        ImGui::TextColored(colour(verdict.neutral ? pal::kRender
                                                  : (verdict.bad ? pal::kBad : pal::kGood)),
                           "%s", verdict.text.c_str());
      }
    }
    top = ImGui::GetWindowHeight();
  }
  ImGui::End();

  ImGui::SetNextWindowPos({x0, y0 + size.y}, ImGuiCond_Always, {0, 1});
  ImGui::SetNextWindowSize({panelsW, 0}, ImGuiCond_Always);
  float bottom = 0.0f;
  if (ImGui::Begin("Legend", nullptr, kOverlay)) {
    // Legend columns wide enough to keep its labels whole.
    const palette::LegendScope scope = legendScopeOf(s.primary());
    legendContents(legendColumns(panelsW, scope), scope);
    bottom = ImGui::GetWindowHeight();
  }
  ImGui::End();

  const float w = std::floor(panelsW / static_cast<float>(n));
  const float h = std::max(size.y - top - bottom, 100.0f);
  for (std::size_t k = 0; k < n; ++k) {
    Source& src = s.panel(k);
    DebuggerState& st = v.panels[k];
    // Nothing covers a comparison's panels (title and legend sit outside them): a margin left
    // from the one-panel view would shrink every framing.
    st.coveredTop = st.coveredBottom = 0.0f;
    std::string name = whatIf ? (k == 0 ? "recorded" : "what-if: " + src.moverName())
                              : src.moverName();
    if (beforeAfter && k == 0) name = "before: " + name;
    if (beforeAfter && k + 1 == n) name = "after: " + name;
    // The id is the panel's place, so a title that changes (before/after) keeps the window.
    name += "###panel" + std::to_string(k);
    place({x0 + w * static_cast<float>(k), y0 + top}, {w, h});
    if (ImGui::Begin(name.c_str(), nullptr, kFixed | ImGuiWindowFlags_NoScrollbar)) {
      // A narrow panel gets a line more, for the verdict's counts.
      const float lines = (src.sim() ? 3.0f : 2.0f) + (w < 420.0f ? 1.0f : 0.0f);
      const float stats = ImGui::GetTextLineHeightWithSpacing() * lines + 4.0f;
      const ImVec2 avail = ImGui::GetContentRegionAvail();
      if (auto pick = worldView("##world", src, st, {avail.x, std::max(avail.y - stats, 40.0f)},
                                &v.failures, k)) {
        a.item = pick;
        a.inspect = k;
      }
      panelStats(s, k, w);
    }
    ImGui::End();
  }
  drawColumn(s, v, {x0 + panelsW, y0, side, size.y}, a);
}

void overlaid(Session& s, ViewState& v, ImVec2 origin, ImVec2 size, float side, Actions& a) {
  onePanel(s, v, origin, size, side, a);
  // Appends to the world view's window, so the other movers are drawn under the panels.
  ImGui::Begin("World");
  ImDrawList& dl = *ImGui::GetWindowDrawList();
  const Camera& cam = v.panels.front().camera;
  dl.PushClipRect(cam.screenMin(), cam.screenMax(), true);
  for (std::size_t k = 1; k < s.size(); ++k) {
    const ImU32 tint = pal::kCompareTints[(k - 1) % std::size(pal::kCompareTints)];
    const WorldPicture pic = s.panel(k).picture();
    for (const sim::Body& b : pic.bodies) {
      if (!cam.sees(b.rect)) continue;
      dl.AddRect(cam.toScreenMin(b.rect), cam.toScreenMax(b.rect), tint, 0.0f, 0, 1.5f);
    }
    if (!pic.moves.empty()) {
      const MoveTrace& m = pic.moves.back().trace;
      const Rect end = m.start.at(m.final);
      dl.AddLine(cam.toScreen(m.start.center()), cam.toScreen(end.center()), tint, 2.0f);
    }
  }
  dl.PopClipRect();
  ImGui::End();

  // Which outline is which mover, under the HUD.
  ImGui::SetNextWindowBgAlpha(0.82f);
  ImGui::SetNextWindowPos({cam.screenMin().x + 8.0f, cam.screenMin().y + v.panels[0].coveredTop},
                          ImGuiCond_Always);
  if (ImGui::Begin("Overlaid", nullptr,
                   ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                       ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                       ImGuiWindowFlags_NoNav)) {
    ImGui::Text("%s: the usual colours", s.primary().moverName().c_str());
    for (std::size_t k = 1; k < s.size(); ++k) {
      const ImU32 tint = pal::kCompareTints[(k - 1) % std::size(pal::kCompareTints)];
      std::string counts;
      if (const SimSource* sim = s.panel(k).sim()) {
        counts = "   (tunnelled " + std::to_string(sim->simulation().counters().tunnelled) + ")";
      }
      ImGui::TextColored(colour(tint), "%s: outlines and path%s", s.panel(k).moverName().c_str(),
                         counts.c_str());
    }
  }
  ImGui::End();
}

// [SECTION] the column ----------------------------------------------------------------------------

void drawColumn(Session& s, ViewState& v, const Column& c, Actions& a) {
  Source& first = s.primary();
  float y = 0.0f;
  if (SimSource* sim = first.sim()) {
    ImGui::SetNextWindowPos({c.x, c.y}, ImGuiCond_Always);
    ImGui::SetNextWindowSize({c.w, 0}, ImGuiCond_Always);
    if (ImGui::Begin("Scene and mover", nullptr, kFixed)) {
      if (s.comparing()) ImGui::TextColored(colour(pal::kDim), "parameters apply to every compared mover");
      a.add(controlsContents(*sim, v.panels.front()));
      // Its Overlays checkboxes show the first panel's and set every panel's, as the View menu
      // does: compared panels draw the same layers.
      for (auto& st : v.panels) st.overlays = v.panels.front().overlays;
      y = ImGui::GetWindowHeight();
    }
    ImGui::End();
  } else {
    // A recording's calls are its controls: time within a frame.
    y = std::floor(std::clamp(c.h * 0.34f, 120.0f, 260.0f));
    char title[96];
    std::snprintf(title, sizeof title, "Calls in frame %" PRIu64 " (%zu)###Calls", first.frame(),
                  first.calls().size());
    place({c.x, c.y}, {c.w, y});
    if (ImGui::Begin(title, nullptr, kFixed)) callsContents(first, v.revealCall, a);
    ImGui::End();
  }
  place({c.x, c.y + y}, {c.w, std::max(c.h - y, 60.0f)});
  v.tabsPos = {c.x, c.y + y};
  v.tabsSize = {c.w, std::max(c.h - y, 60.0f)};
  if (ImGui::Begin("Details", nullptr, kFixed | ImGuiWindowFlags_NoTitleBar)) {
    if (ImGui::BeginTabBar("details")) {
      const auto flag = [&](Tab t) {
        return v.showTab && *v.showTab == t ? ImGuiTabItemFlags_SetSelected : 0;
      };
      const std::size_t k = std::min(v.inspected, s.size() - 1);
      Source& inspected = s.panel(k);
      if (ImGui::BeginTabItem("Inspector###inspector", nullptr, flag(Tab::inspector))) {
        ImGui::BeginChild("inspector");
        if (s.comparing()) {
          // Which panel this is: a click on a body in another panel inspects that one.
          ImGui::TextColored(colour(pal::kDim), "%s (click in a panel to inspect it)",
                             s.whatIf() && k == 0 ? "recorded run" : inspected.moverName().c_str());
        }
        inspectorContents(inspected, &v.failures, k);
        ImGui::EndChild();
        ImGui::EndTabItem();
      }
      if (first.sim() && ImGui::BeginTabItem("Calls###calls", nullptr, flag(Tab::calls))) {
        ImGui::BeginChild("calls");
        callsContents(first, v.revealCall, a);
        ImGui::EndChild();
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Items###items", nullptr, flag(Tab::items))) {
        itemsContents(first, v.items, a);
        ImGui::EndTabItem();
      }
      char failures[64];
      std::snprintf(failures, sizeof failures, "Failures %zu%s###failures",
                    v.failures.entries.size(), v.failures.complete ? "" : "+");
      // A still does not look for failures: no count it has not made.
      if (!v.failures.note.empty() && v.failures.entries.empty())
        std::snprintf(failures, sizeof failures, "Failures###failures");
      if (ImGui::BeginTabItem(failures, nullptr, flag(Tab::failures))) {
        ImGui::BeginChild("failures");
        const auto all = s.panels();
        failuresContents(all, v.failures, v.shownFailure, v.revealFailure, a);
        ImGui::EndChild();
        ImGui::EndTabItem();
      }
      // A comparison shows each panel's counts under it; one panel has room for them all here.
      if (const SimSource* sim = inspected.sim(); sim && !s.comparing() &&
          ImGui::BeginTabItem("Counters###counters", nullptr, flag(Tab::counters))) {
        countersContents(*sim);
        ImGui::EndTabItem();
      }
      v.showTab.reset();
      ImGui::EndTabBar();
    }
  }
  ImGui::End();
}

}  // namespace

// [SECTION] the view ------------------------------------------------------------------------------

std::optional<std::size_t> firstFailureIndex(const FailureList& list) {
  std::optional<std::size_t> first;
  for (std::size_t i = 0; i < list.entries.size(); ++i) {
    if (!first || list.entries[i].failure.frame < list.entries[*first].failure.frame) first = i;
  }
  return first;
}

void goToFailure(Session& s, ViewState& v, std::size_t index) {
  if (index >= v.failures.entries.size()) return;
  const FailureList::Entry e = v.failures.entries[index];
  s.showFailure(e.failure);
  syncPanels(v, s);
  v.inspected = std::min(e.panel, s.size() - 1);
  v.showTab = Tab::inspector;
  v.revealCall = true;
  v.shownFailure = index;
  v.revealFailure = true;
  // Centred and zoomed on the failing move, in every panel.
  const Rect r = s.followView();
  for (DebuggerState& st : v.panels) st.frameView = r;
}

Actions sessionView(Session& s, ViewState& v, ImVec2 origin, ImVec2 size) {
  syncPanels(v, s);
  Actions a;
  if (!s.comparing()) {
    // The column keeps the inspector's hit table readable; the world gets the rest.
    onePanel(s, v, origin, size, std::clamp(size.x * 0.35f, 340.0f, 480.0f), a);
  } else if (v.overlaid) {
    overlaid(s, v, origin, size, std::clamp(size.x * 0.35f, 340.0f, 480.0f), a);
  } else {
    sideBySide(s, v, origin, size, std::clamp(size.x * 0.30f, 340.0f, 440.0f), a);
  }
  return a;
}

}  // namespace tv::ui
