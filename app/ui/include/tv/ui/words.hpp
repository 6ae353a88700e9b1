#pragma once
/// What happened, in words: a move's failure as the scene's rules counted it ("tunnelled through
/// wall"), and what any traced move did as its trace says ("slid along solid 12", "pushed out
/// sideways by solid 40"). The inspector and the world view say these, so a person reads what
/// happened instead of working it out from the overlays.

#include <optional>
#include <string>

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

}  // namespace tv::ui
