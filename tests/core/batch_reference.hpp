#pragma once
// The all-pairs batch step, the reference for tv::Batch (see batch_reference.cpp).

#include <span>
#include <vector>

#include "tv/batch.hpp"

namespace tv::reference {

struct Outcome {
  Vec2 position;
  std::vector<Collision> collisions;
};

/// What tv::Batch::step did before its broad phase: the same validation, events and outcomes.
std::vector<Outcome> batchStep(World& world, std::span<const BatchMove> moves, Filter filter = {},
                               int maxEvents = 4096);

}  // namespace tv::reference
