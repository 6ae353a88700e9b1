// The panels: controls, inspector, counters, HUD and legend, as ImGui widget contents.
#include "tv/app/user_message.hpp"
#include "tv/ui/panels.hpp"

#include <cfloat>
#include <cmath>
#include <cinttypes>
#include <cstdio>
#include <string>

#include "tv/error.hpp"
#include "tv/ui/palette.hpp"

namespace tv::ui {

namespace pal = palette;

namespace {

ImVec4 colour(ImU32 c) {
  return ImGui::ColorConvertU32ToFloat4(c);
}

// A slider's range and scale: what a person tunes, not the whole range a value may take (a
// value typed with Ctrl+click may go beyond it, as far as the parameter allows).
struct SliderRange {
  double lo, hi;
  bool log;
};

SliderRange sliderRange(const sim::ParamSpec& spec) {
  const std::string& n = spec.name;
  if (n == sim::param::speed) return {1.0, 1e6, true};
  if (n == sim::param::dt) return {1e-3, 0.1, true};
  if (n == sim::param::size || n == sim::param::tile || n == sim::param::cell)
    return {0.5, 512.0, true};
  if (n == sim::param::substep) return {0.0, 64.0, false};
  if (n == sim::param::offset) return {0.0, 1e9, true};
  const double lo = std::isfinite(spec.min) ? spec.min : -1e6;
  const double hi = std::isfinite(spec.max) ? spec.max : 1e6;
  return {lo, hi, lo > 0.0 && hi / lo >= 100.0};
}

// Dragged values snap to round numbers: 1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8 times a power of ten
// (Shift: three significant digits, for fine steps).
double snapped(double v, bool fine, bool integer) {
  if (v == 0.0 || !std::isfinite(v)) return v;
  const double mag = std::pow(10.0, std::floor(std::log10(std::abs(v))));
  double out = v;
  if (fine) {
    out = std::round(v / mag * 100.0) * mag / 100.0;
  } else {
    constexpr double kSteps[] = {1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10};
    const double m = std::abs(v) / mag;
    double best = kSteps[0];
    for (const double step : kSteps) {
      if (std::abs(step - m) < std::abs(best - m)) best = step;
    }
    out = std::copysign(best * mag, v);
  }
  return integer ? std::round(out) : out;
}

void rowLabel(const char* text) {
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted(text);
  ImGui::TableSetColumnIndex(1);
  ImGui::SetNextItemWidth(-FLT_MIN);
}

// Applies an edit through Params::set, which validates; a rejected value is reported, not
// clamped, and changes nothing: the parameter goes back to the value that runs. A typed value
// arrives keystroke by keystroke ("1", "1e", "1e9"), so the draft must not keep the "1".
void setDraft(DebuggerState& st, const Session& session, const std::string& name, double v) {
  try {
    st.draft.set(name, v);
    st.error.clear();
  } catch (const Error& e) {
    st.error = app::userMessage(e);
    const sim::SceneDef* scene = sim::builtinScenes().tryFind(st.draftScene);
    const sim::Params running = st.draftScene == session.sim().scene().name || scene == nullptr
                                    ? session.sim().params()
                                    : scene->defaults();
    st.draft.set(name, running.get(name));
  }
}

}  // namespace

void syncDraft(DebuggerState& st, const Session& session) {
  st.draft = session.sim().params();
  st.draftScene = session.sim().scene().name;
  st.draftMover = session.sim().moverSpec();
}

Actions controlsContents(const Session& session, DebuggerState& st) {
  Actions a;
  if (ImGui::BeginTable("choice", 2, ImGuiTableFlags_SizingStretchProp)) {
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed, 172.0f);
    ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
    rowLabel("scene");
    if (ImGui::BeginCombo("##scene", st.draftScene.c_str())) {
      for (const sim::SceneDef& s : sim::builtinScenes().all()) {
        if (ImGui::Selectable(s.name.c_str(), s.name == st.draftScene)) {
          st.draftScene = s.name;
          st.draft = s.defaults();
          a.restart = true;
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", s.description.c_str());
      }
      ImGui::EndCombo();
    }
    rowLabel("mover");
    if (ImGui::BeginCombo("##mover", st.draftMover.name().c_str())) {
      for (const MoverEntry& m : moverTable()) {
        const std::string name(m.name);
        if (ImGui::Selectable(name.c_str(), name == st.draftMover.name())) {
          st.draftMover = m.spec;
          a.restart = true;
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(m.description).c_str());
      }
      ImGui::EndCombo();
    }
    for (const sim::ParamSpec& spec : st.draft.specs()) {
      // Labelled with the flag's name, as in every tool and CSV column.
      const std::string label = spec.name + (spec.unit.empty() ? "" : " (" + spec.unit + ")");
      rowLabel(label.c_str());
      double v = st.draft.get(spec.name);
      const std::string id = "##" + spec.name;
      const SliderRange r = sliderRange(spec);
      const bool changed = ImGui::SliderScalar(
          id.c_str(), ImGuiDataType_Double, &v, &r.lo, &r.hi, spec.integer ? "%.0f" : "%.6g",
          r.log ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None);
      if (changed) {
        // Dragging snaps; a value typed with Ctrl+click is taken exactly.
        const bool dragging = ImGui::IsMouseDown(ImGuiMouseButton_Left);
        if (dragging) v = snapped(v, ImGui::GetIO().KeyShift, spec.integer);
        setDraft(st, session, spec.name, v);
        // Live while the slider moves when a re-run to this tick is cheap; else on release.
        if (dragging && st.lastRerunMs < kLiveRerunMs) a.restart = true;
      }
      if (ImGui::IsItemDeactivatedAfterEdit() && st.error.empty()) a.restart = true;
      if (ImGui::IsItemActive() && st.lastRerunMs >= kLiveRerunMs) {
        ImGui::SetTooltip("re-runs on release (the last re-run took %.0f ms)", st.lastRerunMs);
      } else if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("--%s: %s\ndrag: round values (Shift: fine); Ctrl+click: type exactly",
                          spec.name.c_str(), spec.description.c_str());
      }
    }
    rowLabel("render rate (Hz)");
    // Dragging stays within 0..1000 but a typed value does not: refuse one outside, as
    // tv-render --render-hz does, and keep the rate.
    const double lo = 0.0, hi = 1000.0;
    double hz = st.renderHz;
    const bool edited = ImGui::DragScalar("##render", ImGuiDataType_Double, &hz, 1.0f, &lo, &hi,
                                          "%.0f");
    // Typed keystroke by keystroke ("1", "1e", "1e9"): a refusal goes back to the rate before
    // the edit, not to the "1".
    ImGuiStorage* storage = ImGui::GetStateStorage();
    const ImGuiID before = ImGui::GetID("##render-before");
    if (ImGui::IsItemActivated()) storage->SetFloat(before, static_cast<float>(st.renderHz));
    if (edited) {
      if (std::isfinite(hz) && hz >= lo && hz <= hi) {
        st.renderHz = hz;
        st.error.clear();
      } else {
        st.error = "render rate " + formatNumber(hz) + " Hz refused: it is 0 (none) to 1000 Hz";
        st.renderHz =
            static_cast<double>(storage->GetFloat(before, static_cast<float>(st.renderHz)));
      }
    }
    rowLabel("traced body");
    // Typed as a number, so that 1e9 is read as 1e9 (an integer field kept the digits: 19).
    const std::size_t bodies = session.sim().bodies().size();
    double body = session.selected() ? static_cast<double>(*session.selected()) : -1.0;
    const double one = 1.0;
    if (ImGui::InputScalar("##body", ImGuiDataType_Double, &body, &one, nullptr, "%.0f",
                           ImGuiInputTextFlags_EnterReturnsTrue)) {
      if (body == -1.0) {
        st.error.clear();
      } else if (std::isfinite(body) && body >= 0.0 && body == std::floor(body) &&
                 body < static_cast<double>(bodies)) {
        a.select = static_cast<std::size_t>(body);
        st.error.clear();
      } else {
        st.error = "traced body " + formatNumber(body) + " refused: the scene has " +
                   std::to_string(bodies) + " bodies, 0.." + std::to_string(bodies - 1);
      }
    }
    ImGui::EndTable();
  }
  if (!st.error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, colour(pal::kBad));
    ImGui::TextWrapped("%s", st.error.c_str());  // a refusal explains itself: never cut
    ImGui::PopStyleColor();
  }

  // The same names and keys as the timeline's buttons; a narrow column wraps them.
  const auto sameLineIfFits = [](const char* next) {
    ImGui::SameLine();
    const float w = ImGui::CalcTextSize(next).x + ImGui::GetStyle().FramePadding.x * 2.0f;
    if (ImGui::GetContentRegionAvail().x < w) ImGui::NewLine();
  };
  a.restart |= ImGui::Button("Restart (R)");
  sameLineIfFits("Back (,)");
  a.stepBack = ImGui::Button("Back (,)");
  sameLineIfFits("Forward (.)");
  a.step = ImGui::Button("Forward (.)");
  const char* play = st.paused ? "Play (Space)" : "Pause (Space)";
  sameLineIfFits(play);
  a.togglePause = ImGui::Button(play);

  if (ImGui::CollapsingHeader("Overlays") && ImGui::BeginTable("overlays", 3)) {
    for (const OverlayToggle& t : overlayToggles()) {
      ImGui::TableNextColumn();
      ImGui::Checkbox(t.name, &(st.overlays.*t.flag));
    }
    ImGui::EndTable();
  }
  return a;
}

void inspectorContents(const Session& session) {
  const sim::Simulation& s = session.sim();
  if (!session.selected()) {
    ImGui::TextColored(colour(pal::kDim), "no body selected");
    return;
  }
  const std::size_t i = *session.selected();
  const sim::Body& b = s.bodies()[i];
  ImGui::TextWrapped("body %zu  %s", i, b.active ? "moving" : "stopped");
  ImGui::TextWrapped("at (%.3f, %.3f)  size %g x %g", b.rect.x, b.rect.y, b.rect.w, b.rect.h);
  ImGui::TextWrapped("velocity (%.1f, %.1f) px/s", b.velocity.x, b.velocity.y);
  const auto moves = session.moves();
  if (moves.empty()) {
    // Say why: a body that has stopped makes no move, so there is nothing to trace.
    ImGui::TextColored(colour(pal::kDim), "%s",
                       b.active ? "no move traced yet" : "no move traced: the body has stopped");
    return;
  }
  if (!b.active && moves.back().tick < s.ticks()) {
    ImGui::TextColored(colour(pal::kDim), "stopped: its last move was at tick %" PRIu64,
                       moves.back().tick);
  }
  // Newest first: the move on screen is the one to read.
  for (std::size_t k = moves.size(); k-- > 0;) {
    const TracedMove& tm = moves[k];
    const MoveTrace& m = tm.trace;
    ImGui::PushID(static_cast<int>(k));
    const ImGuiTreeNodeFlags open = k + 1 == moves.size() ? ImGuiTreeNodeFlags_DefaultOpen : 0;
    const bool shown = ImGui::TreeNodeEx("move", open, "tick %" PRIu64 " move by %s: %zu hits",
                                         tm.tick, std::string(m.mover).c_str(), m.hits.size());
    if (shown) {
      ImGui::TextWrapped("%zu cells, %zu candidates, %zu legs, %zu substeps", m.cells.size(),
                  m.candidates.size(), m.legs.size(), m.substeps.size());
      ImGui::TextWrapped("(%.3f, %.3f) -> goal (%.3f, %.3f)", m.start.x, m.start.y, m.goal.x, m.goal.y);
      ImGui::TextWrapped("ended at (%.3f, %.3f)", m.final.x, m.final.y);
      // Two lines per hit, the fields of the Collision record as core filled them.
      for (std::size_t h = 0; h < m.hits.size(); ++h) {
        const Collision& c = m.hits[h];
        const std::string response(s.world().responseName(c.response));
        char ti[32];
        std::snprintf(ti, sizeof ti, c.overlaps ? "overlapping" : "ti %.4f", c.ti);
        ImGui::TextColored(colour(pal::kHit), "hit %zu", h + 1);
        ImGui::SameLine();
        ImGui::TextWrapped("%s  %s  normal %+.0f,%+.0f  %s%s", session.describe(c.other).c_str(), ti,
                    c.normal.x + 0.0, c.normal.y + 0.0, response.c_str(),
                    c.corner ? " (corner)" : "");
        ImGui::PushStyleColor(ImGuiCol_Text, colour(pal::kDim));
        // One point a line, unwrapped: ImGui wraps after a '.', which split "87.000" in two.
        ImGui::Text("   touch (%.3f, %.3f)", c.touch.x, c.touch.y);
        ImGui::Text("   target (%.3f, %.3f)", c.target.x, c.target.y);
        ImGui::PopStyleColor();
      }
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
}

void countersContents(const Session& session) {
  const sim::Simulation& s = session.sim();
  const sim::Counters& c = s.counters();
  // Rows a scene does not use stay hidden; a failure count that is not zero shows red.
  struct Row {
    const char* name;
    std::uint64_t value;
    bool always;
    bool failure;
  };
  const Row rows[] = {
      {"tunnelled so far", c.tunnelled, true, true},
      {"far-side push-outs", c.farPushOuts, false, true},
      {"hits", c.hits, true, false},
      {"misses", c.misses, false, false},
      {"escapes", c.escapes, false, true},
      {"overlaps", c.overlaps, false, true},
      {"jitter", c.jitter, false, true},
      {"snags", c.snags, false, true},
      {"jumps", c.jumps, false, false},
      {"landings", c.landings, false, false},
      {"respawns", c.respawns, false, false},
      {"moves", c.moves, true, false},
      {"collisions", c.collisions, true, false},
  };
  if (ImGui::BeginTable("counters", 2, ImGuiTableFlags_SizingStretchProp)) {
    for (const Row& r : rows) {
      if (!r.always && r.value == 0) continue;
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(r.name);
      ImGui::TableNextColumn();
      const bool bad = r.failure && r.value != 0;
      ImGui::TextColored(colour(bad ? pal::kBad : pal::kLabel), "%" PRIu64, r.value);
    }
    const sim::TraceStats& t = s.traceStats();
    const auto moves = session.moves();
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("candidates per move");
    ImGui::TableNextColumn();
    if (t.moves > 0) {
      ImGui::Text("%zu last, %.2f mean", moves.empty() ? 0 : moves.back().trace.candidates.size(),
                  static_cast<double>(t.candidates) / static_cast<double>(t.moves));
    } else {
      // A traced body that has not moved yet is not "no traced body".
      ImGui::TextColored(colour(pal::kDim), session.selected() ? "(no move yet)" : "(no traced body)");
    }
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("cells per move");
    ImGui::TableNextColumn();
    if (t.moves > 0) {
      ImGui::Text("%zu last, %.2f mean", moves.empty() ? 0 : moves.back().trace.cells.size(),
                  static_cast<double>(t.cells) / static_cast<double>(t.moves));
    }
    ImGui::EndTable();
  }
}

void hudContents(const Session& session, const DebuggerState& st) {
  const sim::Simulation& s = session.sim();
  ImGui::Text("%s", s.scene().name.c_str());
  ImGui::SameLine();
  ImGui::TextColored(colour(pal::kDim), "|");
  ImGui::SameLine();
  ImGui::Text("%s", s.moverSpec().name().c_str());
  ImGui::SameLine();
  ImGui::TextColored(colour(pal::kDim), "|");
  ImGui::SameLine();
  ImGui::Text("tick %" PRIu64, s.ticks());
  ImGui::SameLine();
  ImGui::TextColored(colour(pal::kDim), "|");
  ImGui::SameLine();
  ImGui::TextColored(colour(st.paused ? pal::kRender : pal::kGood),
                     st.paused ? "paused" : "running");
  // The timing line holds only simulated time: a wall-clock value would break byte-exact goldens.
  char render[32] = "= tick";
  if (session.interpolating()) std::snprintf(render, sizeof render, "%.0f Hz", st.renderHz);
  ImGui::TextColored(colour(pal::kDim), "dt %.2f ms   render %s   alpha %.3f   zoom %.2f px/unit",
                     s.dt() * 1000.0, render, session.interpolating() ? s.alpha() : 1.0,
                     st.camera.scale());
}

void legendContents(int columns, bool withCategories) {
  if (!ImGui::BeginTable("legend", columns)) return;
  for (const pal::LegendEntry& e : pal::legend(withCategories)) {
    ImGui::TableNextColumn();
    const ImVec2 p = ImGui::GetCursorScreenPos();
    const float s = ImGui::GetTextLineHeight();
    ImDrawList& dl = *ImGui::GetWindowDrawList();
    const ImVec2 a{p.x + 1, p.y + 1}, b{p.x + s - 1, p.y + s - 1};
    const ImVec2 mid{(a.x + b.x) * 0.5f, (a.y + b.y) * 0.5f};
    switch (e.swatch) {
      case pal::Swatch::fill:
        dl.AddRectFilled(a, b, e.colour | IM_COL32_A_MASK);
        break;
      case pal::Swatch::outline:
        dl.AddRect(a, b, e.colour, 0.0f, 0, 2.0f);
        break;
      case pal::Swatch::line:
        dl.AddLine({a.x, mid.y}, {b.x, mid.y}, e.colour, 2.0f);
        break;
      case pal::Swatch::arrow:
        dl.AddLine({a.x, mid.y}, {b.x - 4, mid.y}, e.colour, 1.5f);
        dl.AddTriangleFilled({b.x, mid.y}, {b.x - 5, mid.y - 4}, {b.x - 5, mid.y + 4}, e.colour);
        break;
      case pal::Swatch::dot:
        dl.AddCircleFilled(mid, 3.5f, e.colour);
        break;
      case pal::Swatch::dashed:
        for (float x = a.x; x < b.x; x += 4.0f) {
          dl.AddLine({x, a.y + 0.5f}, {x + 2, a.y + 0.5f}, e.colour);
          dl.AddLine({x, b.y - 0.5f}, {x + 2, b.y - 0.5f}, e.colour);
        }
        dl.AddLine({a.x + 0.5f, a.y}, {a.x + 0.5f, b.y}, e.colour);
        dl.AddLine({b.x - 0.5f, a.y}, {b.x - 0.5f, b.y}, e.colour);
        break;
    }
    ImGui::Dummy({s, s});
    ImGui::SameLine();
    ImGui::TextUnformatted(e.label);
  }
  ImGui::EndTable();
}

}  // namespace tv::ui
