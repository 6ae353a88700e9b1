#pragma once
// The batch step written the obvious way, the reference for tv::Batch (see batch_reference.cpp).

#include <span>
#include <vector>

#include "tv/batch.hpp"

namespace tv::reference {

struct Outcome {
  Vec2 position;
  std::vector<Collision> collisions;
};

/// tv::Batch::step's semantics with no broad phase, no queue and no caching: before each event
/// every body is searched against the world and every pair against each other, and the least
/// event (time, statics before pairs, add orders) runs. O(N²) an event. Valid input only.
/// `instants`, when given, receives the instant of each event that ran, in order.
std::vector<Outcome> batchStep(World& world, std::span<const BatchMove> moves, Filter filter = {},
                               int maxEvents = 4096, std::vector<double>* instants = nullptr);

}  // namespace tv::reference
