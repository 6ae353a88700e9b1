#pragma once
// The frame-time model of a render loop, shared by the tunnel and jitter studies so that both
// describe the same machine:
//   frame = (1 / rate) · (1 + U(-jitter, +jitter)), and with probability `hitchChance` a hitch
//   instead: (1 / rate) · U(hitchMin, hitchMax).
// Defaults: ±25% jitter; 1 frame in 50 hitches to 2–6 frame periods (33–100 ms at 60 Hz), the
// stalls of a garbage collection, an asset load or a busy OS.

#include <cstdint>
#include <string>

#include "tv/sim/rng.hpp"

namespace tv::bench {

using sim::Rng;  // the scenes' deterministic source, for the seeded frame times too

struct FrameModel {
  double rate = 60.0;         ///< Hz, the render loop's nominal rate
  double jitter = 0.25;       ///< relative half-width of the ordinary frame-time spread
  double hitchChance = 0.02;  ///< probability that a frame is a hitch
  double hitchMin = 2.0;      ///< hitch length in nominal frames, lower bound
  double hitchMax = 6.0;      ///< upper bound

  /// One line for the output: what the numbers were measured under.
  [[nodiscard]] std::string describe() const;
};

class FrameClock {
 public:
  FrameClock(FrameModel model, std::uint64_t seed) : model_(model), rng_(seed) {}
  /// The next frame's duration, s.
  double next() {
    const double period = 1.0 / model_.rate;
    if (rng_.uniform() < model_.hitchChance) {
      return period * rng_.uniform(model_.hitchMin, model_.hitchMax);
    }
    return period * (1.0 + rng_.uniform(-model_.jitter, model_.jitter));
  }

 private:
  FrameModel model_;
  Rng rng_;
};

}  // namespace tv::bench
