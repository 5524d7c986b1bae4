#pragma once
// Inline SVG charts for report.html (issue 15): no scripts, no fonts, no network; each chart is
// an <svg class="plot"> element with axes, ticks, a legend and one polyline per series.
#include <cstdint>
#include <string>
#include <vector>

namespace dynanav {

struct PlotSeries {
  std::string name;
  std::vector<double> x, y;
  uint64_t colour_id = 0;  ///< colourOfId(), so a track has the same colour as in the video
  bool dashed = false;
  bool markers = false;  ///< dots instead of a line (e.g. events on a timeline)
};

struct PlotSpec {
  std::string id;  ///< element id
  std::string title, x_label, y_label;
  int width = 720, height = 300;
  bool equal_aspect = false;  ///< same metres per pixel on both axes (trajectories)
};

std::string svgLinePlot(const PlotSpec& spec, const std::vector<PlotSeries>& series);

/// Horizontal bars (e.g. mean milliseconds per stage), value printed beside each bar.
std::string svgBarChart(const PlotSpec& spec, const std::vector<std::string>& labels,
                        const std::vector<double>& values, const std::string& unit);

/// Escapes &, <, >, " for HTML text and attributes.
std::string htmlEscape(const std::string& text);

}  // namespace dynanav
