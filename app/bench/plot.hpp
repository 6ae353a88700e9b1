#pragma once
// A scatter plot rasterized on the CPU and written as PNG: log x, log y, one numbered point per
// configuration, a key beside the plot from number to label and values, a front drawn through
// chosen points. Text comes from Dear ImGui's built-in
// font atlas (no GL); stb writes the file. Without those libraries `writeScatterPng` says so.

#include <filesystem>
#include <string>
#include <vector>

namespace tv::bench {

struct PlotPoint {
  std::string label;
  double x = 0, y = 0;  ///< y == 0 is drawn on the "exact (0)" line below the axis range
  bool bad = false;     ///< drawn in the warning colour (e.g. it tunnels)
  bool front = false;   ///< on the front: joined by the front line
  std::vector<std::string> keyValues;  ///< shown in the key after the label, one per keyColumns
};

struct ScatterPlot {
  std::string title, subtitle, xLabel, yLabel;
  std::string legendGood, legendBad, legendFront;
  std::vector<std::string> keyColumns;  ///< titles of the key's value columns (right-aligned)
  std::vector<PlotPoint> points;
};

/// True when the program was built with the plotting libraries.
[[nodiscard]] bool canPlot();
/// Writes the plot; throws std::runtime_error when it cannot (or when canPlot() is false).
void writeScatterPng(const ScatterPlot& plot, const std::filesystem::path& path);

}  // namespace tv::bench
