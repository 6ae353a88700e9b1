// The inspector: the selected call or the traced item's moves, in words and in full.
#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <string>
#include <vector>

#include "tv/ui/palette.hpp"
#include "tv/ui/panels.hpp"
#include "tv/ui/replay_source.hpp"
#include "tv/ui/sim_source.hpp"
#include "tv/ui/words.hpp"

namespace tv::ui {

namespace pal = palette;

namespace {

ImVec4 colour(ImU32 c) {
  return ImGui::ColorConvertU32ToFloat4(c);
}

std::string responseText(const World& world, ResponseId r) {
  if (r == response::ignore) return "ignore";
  // A user response registered later than this frame would not be known to the world here.
  try {
    return std::string(world.responseName(r));
  } catch (const std::exception&) {
    return "response " + std::to_string(r);
  }
}

// The move's failure: the source's own (a scene counted it), else the Failures list's.
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

void saidLine(const Said& said) {
  ImGui::PushStyleColor(ImGuiCol_Text, colour(said.bad ? pal::kBad : pal::kGood));
  ImGui::TextWrapped("%s", said.text.c_str());
  ImGui::PopStyleColor();
}

void traceDetails(const Source& s, const MoveTrace& m) {
  const World& w = s.world();
  ImGui::TextWrapped("(%.3f, %.3f) -> goal (%.3f, %.3f)", m.start.x, m.start.y, m.goal.x, m.goal.y);
  ImGui::TextWrapped("ended at (%.3f, %.3f)%s%s", m.final.x, m.final.y, m.mover.empty() ? "" : "  by ",
                     std::string(m.mover).c_str());
  if (ImGui::TreeNodeEx("cells", 0, "cells visited: %zu", m.cells.size())) {
    std::string line;
    for (std::size_t k = 0; k < m.cells.size(); ++k) {
      char cell[48];
      std::snprintf(cell, sizeof cell, "(%lld,%lld) ", static_cast<long long>(m.cells[k].x),
                    static_cast<long long>(m.cells[k].y));
      line += cell;
      if ((k + 1) % 6 == 0 || k + 1 == m.cells.size()) {
        ImGui::TextWrapped("%s", line.c_str());
        line.clear();
      }
    }
    ImGui::TreePop();
  }
  // Each candidate once, with what the filter answered for it (if it was asked: only items the
  // move would meet first are).
  std::vector<ItemId> seen;
  for (const ItemId id : m.candidates) {
    if (std::find(seen.begin(), seen.end(), id) == seen.end()) seen.push_back(id);
  }
  if (ImGui::TreeNodeEx("candidates", ImGuiTreeNodeFlags_DefaultOpen,
                        "candidates tested: %zu (%zu distinct)", m.candidates.size(), seen.size())) {
    for (const ItemId id : seen) {
      std::string answers;
      for (const TraceAnswer& ans : m.answers) {
        if (ans.other != id) continue;
        answers += (answers.empty() ? "" : ", ") + responseText(w, ans.response);
      }
      ImGui::TextColored(colour(pal::kCandidate), "%s", s.describe(id).c_str());
      ImGui::SameLine();
      if (answers.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, colour(pal::kDim));
        ImGui::TextWrapped("filter not asked (not met first)");
        ImGui::PopStyleColor();
      } else {
        ImGui::TextWrapped("filter: %s", answers.c_str());
      }
    }
    ImGui::TreePop();
  }
  if (ImGui::TreeNodeEx("legs", 0, "sweeps: %zu, substeps: %zu", m.legs.size(),
                        m.substeps.size())) {
    for (std::size_t k = 0; k < m.legs.size(); ++k) {
      const TraceLeg& l = m.legs[k];
      ImGui::TextColored(colour(pal::kSweep), "leg %zu", k + 1);
      ImGui::SameLine();
      ImGui::TextWrapped("(%.3f, %.3f) -> (%.3f, %.3f)", l.start.x, l.start.y, l.goal.x, l.goal.y);
    }
    ImGui::TreePop();
  }
  // Two lines per hit: the fields of the Collision record as core filled them.
  for (std::size_t h = 0; h < m.hits.size(); ++h) {
    const Collision& c = m.hits[h];
    char ti[32];
    std::snprintf(ti, sizeof ti, c.overlaps ? "overlapping" : "ti %.4f", c.ti);
    ImGui::TextColored(colour(pal::kHit), "hit %zu", h + 1);
    ImGui::SameLine();
    ImGui::TextWrapped("%s  %s  normal %+.0f,%+.0f%s", s.describe(c.other).c_str(), ti,
                       c.normal.x + 0.0, c.normal.y + 0.0, c.corner ? " (corner)" : "");
    // One point a line, unwrapped: ImGui wraps after a '.', which split "87.000" in two.
    ImGui::TextColored(colour(pal::kDim), "   touch (%.3f, %.3f)", c.touch.x, c.touch.y);
    ImGui::TextColored(colour(pal::kResponse), "   %s -> (%.3f, %.3f)",
                       responseText(w, c.response).c_str(), c.target.x, c.target.y);
  }
}

void callContents(const Source& s, const CallInfo& c, const FailureList* list, std::size_t panel) {
  ImGui::TextWrapped("call %u of %s %" PRIu64 ": %s", c.index, frameWord(s), c.frame,
                     std::string(tv::callWords(c.kind)).c_str());
  ImGui::TextWrapped("%s", c.summary.c_str());
  if (c.item.valid()) {
    const std::string cat = s.category(c.item);
    ImGui::TextWrapped("item: %s%s%s", s.describe(c.item).c_str(), cat.empty() ? "" : "  category ",
                       cat.c_str());
  }
  if (const MoveTrace* m = s.callTrace()) {
    const TracedMove tm{c.frame, *m};
    const auto failed = failureFor(s, tm, list, panel);
    saidLine(whatHappened(*m, s, failed ? &*failed : nullptr));
    // A recording says where the game's move ended; a re-run that ends elsewhere says so.
    if (s.replay() && m->final != c.position) {
      ImGui::PushStyleColor(ImGuiCol_Text, colour(s.openLoop() ? pal::kRender : pal::kBad));
      ImGui::TextWrapped("recorded end (%.3f, %.3f), %s (%.3f, %.3f)", c.position.x, c.position.y,
                         s.openLoop() ? "this run" : "replayed", m->final.x, m->final.y);
      ImGui::PopStyleColor();
    }
    traceDetails(s, *m);
  } else if (c.kind == CallKind::queryRect || c.kind == CallKind::queryPoint ||
             c.kind == CallKind::querySegment || c.kind == CallKind::anyOverlap) {
    ImGui::TextColored(colour(pal::kDim), "%u results recorded (a query sweeps nothing)", c.hits);
  } else if (!s.traces(c)) {
    ImGui::TextColored(colour(pal::kDim), "nothing is swept by %s, so there is no trace",
                       std::string(tv::callWords(c.kind)).c_str());
  } else {
    ImGui::TextColored(colour(pal::kDim), "no trace (a batch moves every body at once)");
  }
}

}  // namespace

void inspectorContents(const Source& s, const FailureList* failures, std::size_t panel) {
  if (const ReplaySource* r = s.replay()) {
    // The same words as the picture's label and the status bar: what is drawn here came from
    // a world whose replay went another way than the game.
    if (const std::string label = r->pictureLabel(); !label.empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, colour(pal::kBad));
      ImGui::TextWrapped("%s", label.c_str());
      ImGui::PopStyleColor();
    }
  }
  if (const auto k = s.call(); k && *k < s.calls().size()) {
    callContents(s, s.calls()[*k], failures, panel);
    return;
  }
  const auto traced = s.traced();
  if (!traced) {
    ImGui::TextColored(colour(pal::kDim), "%s",
                       s.replay() ? "select a call, an item (Items) or click a body to trace it"
                                  : "no body traced: click one, or pick one in Items");
    return;
  }
  const ItemId id = *traced;
  const std::string cat = s.category(id);
  const SimSource* sim = s.sim();
  const sim::Body* body = nullptr;
  if (sim) {
    if (const auto b = sim->bodyOf(id)) body = &sim->simulation().bodies()[*b];
  }
  ImGui::TextWrapped("%s%s%s%s", s.describe(id).c_str(), cat.empty() ? "" : "  ", cat.c_str(),
                     body ? (body->active ? "  moving" : "  stopped") : "");
  if (s.world().has(id)) {
    const Rect r = s.world().rect(id);
    ImGui::TextWrapped("at (%.3f, %.3f)  size %g x %g", r.x, r.y, r.w, r.h);
  } else {
    ImGui::TextColored(colour(pal::kDim), "not in the world at this %s", frameWord(s));
  }
  if (body) ImGui::TextWrapped("velocity (%.1f, %.1f) px/s", body->velocity.x, body->velocity.y);
  const auto moves = s.history();
  if (moves.empty()) {
    // Say why: a body that has stopped makes no move, so there is nothing to trace; an item
    // not in the world (said above) makes none either.
    if (s.world().has(id) || body) {
      // Bodies moved by a core function other than a mover's move keep no trace: say by what.
      const char* why = body && !body->active ? "no move traced: the body has stopped"
                        : body && body->solid
                            ? "a moving solid (tv::moveSolid): its moves are not traced; the "
                              "bodies it carried, pushed or squished are outlined"
                        : body && body->maxNudge > 0.0
                            ? "moved with corner correction (tv::moveCornered): its moves are "
                              "not traced; each nudge is drawn (green)"
                            : "no move of it traced yet";
      ImGui::PushStyleColor(ImGuiCol_Text, colour(pal::kDim));
      ImGui::TextWrapped("%s", why);
      ImGui::PopStyleColor();
    }
    return;
  }
  if (body && !body->active && moves.back().tick < s.frame()) {
    ImGui::TextColored(colour(pal::kDim), "stopped: its last move was at %s %" PRIu64,
                       frameWord(s), moves.back().tick);
  }
  // Newest first: the move on screen is the one to read.
  for (std::size_t k = moves.size(); k-- > 0;) {
    const TracedMove& tm = moves[k];
    ImGui::PushID(static_cast<int>(k));
    const ImGuiTreeNodeFlags open = k + 1 == moves.size() ? ImGuiTreeNodeFlags_DefaultOpen : 0;
    const auto failed = failureFor(s, tm, failures, panel);
    if (failed) ImGui::PushStyleColor(ImGuiCol_Text, colour(pal::kBad));
    const bool shown = ImGui::TreeNodeEx("move", open, "%s %" PRIu64 " move by %s: %zu hits%s",
                                         frameWord(s), tm.tick, std::string(tm.trace.mover).c_str(),
                                         tm.trace.hits.size(), failed ? " (failed)" : "");
    if (failed) ImGui::PopStyleColor();
    if (shown) {
      saidLine(whatHappened(tm.trace, s, failed ? &*failed : nullptr));
      traceDetails(s, tm.trace);
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
}

}  // namespace tv::ui
