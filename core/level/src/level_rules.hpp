#pragma once
// The rules of a level loaded from a file: walkers, players, bullets and fliers
// (tv::level::Motion). Internal to tv::level.

#include <memory>
#include <vector>

#include "tv/level/level.hpp"
#include "tv/sim/scene.hpp"

namespace tv::level::detail {

/// What the rules keep for one body (constant: everything that changes lives in the body).
struct BodyRule {
  Motion motion = Motion::fly;
  double speed = 0.0;  // px/s: walkers and players
  JumpScript jump;     // players; speed resolved
  Vec2 start;          // players respawn here
};

/// `killY`: a player whose top passes below it respawns at its start.
std::shared_ptr<const sim::SceneRules> makeLevelRules(std::vector<BodyRule> bodies, double killY);

}  // namespace tv::level::detail
