#pragma once
// The timeline: a bar over the ticks that can be reached, the current tick, and marks where
// compared movers part ways. Drawn by hand rather than as a slider so the marks sit exactly on
// their ticks.

#include <cstdint>
#include <optional>
#include <string>

#include "imgui.h"

namespace tv::viewer {

struct TimelineMarks {
  std::optional<std::uint64_t> difference;  ///< first tick the movers' states differ
  std::optional<std::uint64_t> failure;     ///< first tick one failed (tunnelled...)
  std::string failureText;
  std::uint64_t known = 0;  ///< ticks the look-ahead has covered
  const char* unit = "tick";  ///< what a step of the bar is called ("frame" for recordings)
};

/// The bar, `width` x one frame height, covering ticks [0, last]. Returns the tick clicked or
/// dragged to.
std::optional<std::uint64_t> timelineBar(const char* id, std::uint64_t current, std::uint64_t last,
                                         const TimelineMarks& marks, float width);

}  // namespace tv::viewer
