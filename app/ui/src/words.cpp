// What happened, in words, from what core and the scene's rules recorded.
#include "tv/ui/words.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace tv::ui {

namespace {

std::string named(const Source& s, ItemId id) {
  return id.valid() ? s.describe(id) : std::string("something");
}

}  // namespace

std::optional<Failure> failureOf(const sim::Simulation& sim, const sim::TickEvent& e,
                                 const Source& source) {
  Failure f;
  f.frame = e.tick;
  if (e.body >= 0 && static_cast<std::size_t>(e.body) < sim.bodies().size())
    f.item = sim.bodies()[static_cast<std::size_t>(e.body)].item;
  using sim::Counted;
  switch (e.what) {
    case Counted::tunnelled:
      f.kind = FailureKind::tunnelled;
      f.what = e.other.valid() ? "tunnelled through " + source.describe(e.other) : "tunnelled";
      break;
    case Counted::farPushOut:
      return std::nullopt;  // one of its tunnels, told there
    case Counted::missed:
      if (!sim.scene().missesFail) return std::nullopt;
      f.kind = FailureKind::tunnelled;
      f.what = "missed: crossed its target without meeting it";
      break;
    case Counted::escaped:
      f.kind = FailureKind::escaped;
      f.what = "escaped the space that encloses it";
      break;
    case Counted::overlapped:
      f.kind = FailureKind::overlapping;
      f.what = e.other.valid() ? "ended inside " + source.describe(e.other)
                               : "ended inside a solid";
      break;
    case Counted::jittered:
      f.kind = FailureKind::jittered;
      f.what = "moved while resting (jitter)";
      break;
    case Counted::snagged:
      f.kind = FailureKind::snagged;
      f.what = "snagged on a seam of the floor";
      break;
    case Counted::dropped:
      f.kind = FailureKind::dropped;
      f.what = "dropped by " + named(source, e.other) +
               ": fell into or through the platform it stood on";
      break;
    case Counted::popped:
      f.kind = FailureKind::popped;
      f.what = "popped off " + named(source, e.other) +
               ": left above the platform it stood on, not on it";
      break;
    case Counted::manyCollisions:
      f.kind = FailureKind::busy;
      f.what = std::to_string(e.collisions) + " responses in one move";
      break;
  }
  return f;
}

Said whatHappened(const MoveTrace& m, const Source& s, const Failure* failed) {
  Said said;
  if (failed) {
    said.text = failed->what;
    said.bad = failed->kind != FailureKind::busy;
  }
  const Vec2 move = m.goal - m.start.position();
  std::string did;
  std::string first;  // the first thing it did, alone: the brief form
  if (m.hits.empty()) {
    if (!failed) did = m.final == m.goal ? "moved freely: nothing in the way" : "moved: no hit";
  } else {
    // The first hit says what stopped or turned the move; a second, what followed; the same
    // thing again is counted, not repeated ("pushed back out of wall (4 times)").
    std::size_t told = 0;
    std::string last;
    std::size_t again = 0;
    const auto flush = [&] {
      if (again > 0) did += " (" + std::to_string(again + 1) + " times)";
      again = 0;
    };
    for (const Collision& c : m.hits) {
      const std::string other = named(s, c.other);
      std::string phrase;
      if (c.overlaps) {
        // A push out of an overlap (the discrete mover): which way says whether it went back,
        // sideways (a snag), or out of the far side (a tunnel).
        const double along = c.normal.x * move.x + c.normal.y * move.y;
        if (along > 0.0) {
          phrase = "pushed out of the far side of " + other;
          said.bad = true;
        } else if (along == 0.0 && (move.x != 0.0 || move.y != 0.0)) {
          phrase = "pushed out sideways by " + other;
        } else {
          phrase = "pushed back out of " + other;
        }
      } else if (c.response == response::touch) {
        phrase = "stopped against " + other;
      } else if (c.response == response::slide) {
        // Sliding keeps what is along the surface: with nothing along it, the move stopped
        // there (a fall lands); with nothing moved at all, it was held.
        const double across = move.x * c.normal.y - move.y * c.normal.x;
        if (m.final == m.start.position()) {
          phrase = "held against " + other;
        } else if (across == 0.0) {
          phrase = (c.normal.y < 0.0 ? "landed on " : "stopped against ") + other;
        } else {
          phrase = "slid along " + other;
        }
      } else if (c.response == response::bounce) {
        phrase = "bounced off " + other;
      } else if (c.response == response::cross) {
        phrase = "crossed " + other;
      } else {
        phrase = "met " + other + " (response " + std::to_string(c.response) + ")";
      }
      if (c.corner) phrase += " at a corner";
      if (phrase == last) {
        ++again;
        continue;
      }
      flush();
      if (told == 2) {
        did += ", and more";
        break;
      }
      did += (did.empty() ? "" : ", then ") + phrase;
      if (first.empty()) first = phrase;
      last = phrase;
      ++told;
    }
    flush();
  }
  if (!m.substeps.empty()) {
    did += (did.empty() ? "" : ", ") + std::string("in ") + std::to_string(m.substeps.size() + 1) +
           " pieces";
  }
  if (said.text.empty()) {
    said.text = did;
    said.brief = first.empty() ? did : first;
  } else {
    // The failure's first clause: "tunnelled through wall" of "..., 32 from the recorded end",
    // "ended inside body 1" of "...; dropped by body 1: ...".
    said.brief = said.text.substr(
        0, std::min({said.text.find(", "), said.text.find(" ("), said.text.find("; ")}));
    if (!did.empty()) said.text += " (" + did + ")";
  }
  return said;
}

std::string divergenceWords(const Divergence& d) {
  std::string s = "frame " + std::to_string(d.frame) + " call " + std::to_string(d.call) + ", " +
                  std::string(callWords(d.kind));
  if (!d.item.empty()) s += " " + d.item;
  return s + ": " + d.what + " recorded " + d.expected + ", replayed " + d.got;
}

std::string pictureLabel(const Divergence& d, bool here) {
  return here ? "NOT WHAT THE GAME GOT: the replay differs from the recording at " + divergenceWords(d)
              : "MAY NOT BE WHAT THE GAME GOT: the replay differed from the recording earlier, at " +
                    divergenceWords(d);
}

}  // namespace tv::ui
