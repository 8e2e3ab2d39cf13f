// A small, dependency-free SVG line/scatter plot writer (used by `ssrlab bench --plot`).
//
// Axes with "nice" ticks (1-2-5 steps on linear axes, decades with 2/5 subdivisions on log
// axes), grid, title, axis labels, a legend (colour-blind-friendly palette, one marker shape per
// series), markers, optional polylines and per-point labels. Non-finite points, and non-positive
// values on a log axis, are skipped. Every text is XML-escaped.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace ssr {

struct PlotSeries {
  std::string name;
  std::vector<std::pair<double, double>> points;
  std::vector<std::string> labels;  // optional per-point labels: same size as points, or empty
  bool lines = true;                // join the points (in the given order) with a polyline
};

struct PlotSpec {
  std::string title, x_label, y_label;
  bool log_x = false, log_y = false;
  std::vector<PlotSeries> series;
  int width = 800, height = 500;
};

// The whole SVG document.
std::string svg_plot(const PlotSpec& spec);

// XML-escapes & < > " ' (exposed for tests).
std::string xml_escape(const std::string& text);

}  // namespace ssr
