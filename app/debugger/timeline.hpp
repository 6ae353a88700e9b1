#pragma once
// The timeline: a bar over the ticks that can be reached, the current tick, and marks where
// compared movers part ways. Drawn by hand rather than as a slider so the marks sit exactly on
// their ticks.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "imgui.h"

namespace tv::viewer {

struct TimelineMarks {
  std::optional<std::uint64_t> difference;   ///< first frame the panels' runs differ
  std::optional<std::uint64_t> failure;      ///< first frame one failed (tunnelled...)
  std::optional<std::uint64_t> implausible;  ///< a what-if's goals stop making sense from here
  std::vector<std::uint64_t> failures;       ///< every frame with a failure (small ticks)
  std::string failureText;
  /// A recording's replay differs from it from here (Debugger::divergence), in its words.
  std::optional<std::uint64_t> diverged;
  std::string divergedText;
  std::uint64_t first = 0;  ///< the first frame that can be shown (a live stream drops its oldest)
  std::uint64_t known = 0;  ///< frames the checks have covered
  const char* unit = "tick";  ///< what a step of the bar is called ("frame" for recordings)
};

/// The bar, `width` x one frame height, covering frames [first, last]. Returns the frame clicked
/// or dragged to.
std::optional<std::uint64_t> timelineBar(const char* id, std::uint64_t current, std::uint64_t last,
                                         const TimelineMarks& marks, float width);

}  // namespace tv::viewer
