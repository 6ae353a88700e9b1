// The panels around a tunable source and every source: controls, counters, HUD and legend.
#include "tv/ui/panels.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cinttypes>
#include <cstdio>
#include <string>

#include "tv/app/user_message.hpp"
#include "tv/error.hpp"
#include "tv/ui/replay_source.hpp"
#include "tv/ui/sim_source.hpp"
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
void setDraft(DebuggerState& st, const SimSource& source, const std::string& name, double v) {
  try {
    st.draft.set(name, v);
    st.error.clear();
  } catch (const Error& e) {
    st.error = app::userMessage(e);
    const sim::Simulation& sim = source.simulation();
    const sim::SceneDef* scene = sim::builtinScenes().tryFind(st.draftScene);
    const sim::Params running = st.draftScene == sim.scene().name || scene == nullptr
                                    ? sim.params()
                                    : scene->defaults();
    st.draft.set(name, running.get(name));
  }
}

}  // namespace

void Actions::add(const Actions& o) {
  restart |= o.restart;
  apply |= o.apply;
  step |= o.step;
  stepBack |= o.stepBack;
  togglePause |= o.togglePause;
  if (o.item) item = o.item;
  if (o.call) call = o.call;
  if (o.inspect) inspect = o.inspect;
  if (o.failure) failure = o.failure;
}

const char* frameWord(const Source& source) {
  return source.sim() ? "tick" : "frame";
}

void syncDraft(DebuggerState& st, const SimSource& source) {
  st.draft = source.simulation().params();
  st.draftScene = source.simulation().scene().name;
  st.draftMover = source.simulation().moverSpec();
  st.renderHz = source.renderHz();
}

Actions controlsContents(const SimSource& source, DebuggerState& st) {
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
          a.apply = true;
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
          a.apply = true;
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
      // A substep of 0 means half the smallest item: the field says what it comes to, as the
      // substep sweep does, so the two never read 0 and 8 for the same thing.
      char zero[64];
      const char* format = spec.integer ? "%.0f" : "%.6g";
      if (spec.name == sim::param::substep && v == 0.0) {
        std::snprintf(zero, sizeof zero, "0 = tile/2 = %s px",
                      formatNumber(st.draft.get(sim::param::tile) * 0.5).c_str());
        format = zero;
      }
      const bool changed = ImGui::SliderScalar(
          id.c_str(), ImGuiDataType_Double, &v, &r.lo, &r.hi, format,
          r.log ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None);
      if (changed) {
        // Dragging snaps; a value typed with Ctrl+click is taken exactly.
        const bool dragging = ImGui::IsMouseDown(ImGuiMouseButton_Left);
        if (dragging) v = snapped(v, ImGui::GetIO().KeyShift, spec.integer);
        setDraft(st, source, spec.name, v);
        // Live while the slider moves when a re-run to this tick is cheap; else on release.
        if (dragging && st.lastRerunMs < kLiveRerunMs) a.apply = true;
      }
      if (ImGui::IsItemDeactivatedAfterEdit() && st.error.empty()) a.apply = true;
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
    const std::size_t bodies = source.simulation().bodies().size();
    double body = source.tracedBody() ? static_cast<double>(*source.tracedBody()) : -1.0;
    const double one = 1.0;
    if (ImGui::InputScalar("##body", ImGuiDataType_Double, &body, &one, nullptr, "%.0f",
                           ImGuiInputTextFlags_EnterReturnsTrue)) {
      if (body == -1.0) {
        a.item = std::optional<ItemId>{};
        st.error.clear();
      } else if (std::isfinite(body) && body >= 0.0 && body == std::floor(body) &&
                 body < static_cast<double>(bodies)) {
        a.item = source.simulation().bodies()[static_cast<std::size_t>(body)].item;
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

void countersContents(const SimSource& source) {
  const sim::Simulation& s = source.simulation();
  const sim::Counters& c = s.counters();
  // Rows a scene does not use stay hidden; a failure count that is not zero shows red.
  struct Row {
    const char* name;
    std::uint64_t value;
    bool always;
    bool failure;
    const char* tip = nullptr;  // what the row means, on hover
  };
  const Row rows[] = {
      {"tunnelled so far", c.tunnelled, true, true},
      {"far-side push-outs", c.farPushOuts, false, true},
      {"target hits", c.hits, false, false,
       "what the scene means to be hit and was (a bullet stopped by the wall, a crowd\n"
       "mover meeting a solid); every collision is counted under collisions"},
      {"misses", c.misses, false, false},
      {"escapes", c.escapes, false, true},
      {"overlaps", c.overlaps, false, true},
      {"jitter", c.jitter, false, true},
      {"snags", c.snags, false, true},
      {"jumps", c.jumps, false, false},
      {"landings", c.landings, false, false},
      {"respawns", c.respawns, false, false},
      {"drops", c.drops, false, true},
      {"pops", c.pops, false, true},
      {"squishes", c.squishes, false, false},
      {"moves", c.moves, true, false},
      {"collisions", c.collisions, true, false},
  };
  if (ImGui::BeginTable("counters", 2, ImGuiTableFlags_SizingStretchProp)) {
    for (const Row& r : rows) {
      if (!r.always && r.value == 0) continue;
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(r.name);
      if (r.tip != nullptr && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", r.tip);
      ImGui::TableNextColumn();
      const bool bad = r.failure && r.value != 0;
      ImGui::TextColored(colour(bad ? pal::kBad : pal::kLabel), "%" PRIu64, r.value);
    }
    const sim::TraceStats& t = s.traceStats();
    const auto moves = source.history();
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("candidates per move");
    ImGui::TableNextColumn();
    if (t.moves > 0) {
      ImGui::Text("%zu last, %.2f mean", moves.empty() ? 0 : moves.back().trace.candidates.size(),
                  static_cast<double>(t.candidates) / static_cast<double>(t.moves));
    } else {
      // A traced body that has not moved yet is not "no traced body".
      ImGui::TextColored(colour(pal::kDim), source.traced() ? "(no move yet)" : "(no traced body)");
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

void hudContents(const Source& source, const DebuggerState& st) {
  const auto bar = [] {
    ImGui::SameLine();
    ImGui::TextColored(colour(pal::kDim), "|");
    ImGui::SameLine();
  };
  const SimSource* sim = source.sim();
  ImGui::Text("%s", source.name().c_str());
  bar();
  ImGui::Text("%s", source.moverName().c_str());
  bar();
  if (sim) {
    ImGui::Text("tick %" PRIu64, source.frame());
  } else {
    ImGui::Text("frame %" PRIu64 " (%" PRIu64 "..%" PRIu64 ")", source.frame(),
                source.firstFrame(), source.lastFrame());
  }
  if (const auto k = source.call()) {
    bar();
    ImGui::Text("call %u of %zu", *k, source.calls().size());
  } else if (!sim) {
    bar();
    ImGui::Text("end of frame (%zu calls)", source.calls().size());
  }
  bar();
  ImGui::TextColored(colour(st.paused ? pal::kRender : pal::kGood), st.paused ? "paused" : "running");
  // The timing line holds only simulated time: a wall-clock value would break byte-exact goldens.
  if (sim) {
    const sim::Simulation& s = sim->simulation();
    char render[32] = "= tick";
    if (sim->interpolating()) std::snprintf(render, sizeof render, "%.0f Hz", sim->renderHz());
    ImGui::TextColored(colour(pal::kDim), "dt %.2f ms   render %s   alpha %.3f   zoom %.2f px/unit",
                       s.dt() * 1000.0, render, sim->interpolating() ? s.alpha() : 1.0,
                       st.camera.scale());
  } else {
    const auto traced = source.traced();
    ImGui::TextColored(colour(pal::kDim), "traced: %s   %zu items   zoom %.2f px/unit",
                       traced ? source.describe(*traced).c_str() : "none", source.world().count(),
                       st.camera.scale());
  }
  // What the source wants known (a file cut short, a map with nothing solid), whole.
  for (const std::string& note : source.notes()) {
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 560.0f);
    ImGui::TextColored(colour(pal::kBad), "%s", note.c_str());
    ImGui::PopTextWrapPos();
  }
}

palette::LegendScope legendScopeOf(const Source& source) {
  palette::LegendScope scope;
  const SimSource* sim = source.sim();
  scope.recorded = sim == nullptr;
  if (sim) {
    const sim::Simulation& s = sim->simulation();
    for (const sim::Solid& x : s.solids())
      if (x.oneWay) scope.has |= pal::kWithOneWay;
    for (const sim::Body& b : s.bodies()) {
      if (b.oneWay) scope.has |= pal::kWithOneWay;
      // As the world view draws them: a body in the solid layer is a solid the scene moves.
      if (b.solid || b.layer == sim::kLayerSolid) scope.has |= pal::kWithMovingSolids;
      if (b.maxNudge > 0.0) scope.has |= pal::kWithCornerNudge;
    }
  }
  if (source.hasContacts()) scope.has |= pal::kWithContacts;
  // A recording (or a live game) whose game corrected a corner: its nudges are drawn, so named.
  if (const ReplaySource* r = source.replay(); r && r->hasNudges()) {
    scope.has |= pal::kWithCornerNudge;
  }
  return scope;
}

int legendColumns(float width, palette::LegendScope scope) {
  // A column holds the swatch and the widest label shown, and never less than ~150 px (the
  // scene legend's columns, whose labels are short).
  float widest = 0.0f;
  for (const pal::LegendEntry& e : pal::legend()) {
    if (!scope.shows(e)) continue;
    widest = std::max(widest, ImGui::CalcTextSize(e.label).x);
  }
  const ImGuiStyle& style = ImGui::GetStyle();
  const float column = std::max(150.0f, widest + ImGui::GetTextLineHeight() +
                                            style.ItemSpacing.x + 2.0f * style.CellPadding.x + 4.0f);
  return std::clamp(static_cast<int>(width / column), 1, 8);
}

void legendContents(int columns, palette::LegendScope scope) {
  if (!ImGui::BeginTable("legend", columns)) return;
  for (const pal::LegendEntry& e : pal::legend()) {
    if (!scope.shows(e)) continue;
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
      case pal::Swatch::diamond:
      case pal::Swatch::hollowDiamond: {
        const float r = (b.x - a.x) * 0.4f;
        const ImVec2 d[4] = {{mid.x, mid.y - r}, {mid.x + r, mid.y}, {mid.x, mid.y + r},
                             {mid.x - r, mid.y}};
        if (e.swatch == pal::Swatch::diamond) {
          dl.AddConvexPolyFilled(d, 4, e.colour);
        } else {
          dl.AddPolyline(d, 4, e.colour, ImDrawFlags_Closed, 2.0f);
        }
        break;
      }
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
