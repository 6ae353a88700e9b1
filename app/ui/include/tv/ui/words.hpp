#pragma once
/// What happened, in words: a move's failure as the scene's rules counted it ("tunnelled through
/// wall"), and what any traced move did as its trace says ("slid along solid 12", "pushed out
/// sideways by solid 40"). The inspector and the world view say these, so a person reads what
/// happened instead of working it out from the overlays.

#include <optional>
#include <string>

#include "tv/record/replay.hpp"
#include "tv/sim/simulation.hpp"
#include "tv/trace.hpp"
#include "tv/ui/source.hpp"

namespace tv::ui {

/// An event of `sim` as a failure, in words, naming its body and what it met with `source`'s
/// names; none for what is not a failure in this scene (an expected graze, a far-side push-out
/// already told by its tunnel).
[[nodiscard]] std::optional<Failure> failureOf(const sim::Simulation& sim, const sim::TickEvent& e,
                                               const Source& source);

/// What a move did, in words.
struct Said {
  std::string text;
  std::string brief;  ///< the first clause alone, where the whole does not fit
  bool bad = false;   ///< a failure (drawn red)
};
/// What the move `m` did, from its trace; `failed` (may be null) is its failure, if it failed.
[[nodiscard]] Said whatHappened(const MoveTrace& m, const Source& source, const Failure* failed);

/// A replay's divergence from its recording, in the words every part of the debugger uses for
/// it (the status bar, the timeline's mark, the inspector, the picture's label), so that they
/// cannot disagree: "frame 6 call 0, move player: position recorded (62.3, 16), replayed (32, 16)".
[[nodiscard]] std::string divergenceWords(const Divergence& d);
/// The label of a picture drawn from a world whose replay diverged on the way there: in the
/// frame on screen (`here`), the picture is not what the game got; in an earlier frame replayed
/// for it, it may not be (a later move of the same item may have brought it back).
[[nodiscard]] std::string pictureLabel(const Divergence& d, bool here);

}  // namespace tv::ui
