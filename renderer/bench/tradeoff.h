#pragma once
// The speed-versus-accuracy trade of radview's methods, as `radview bench` measures it: one
// row per method and setting, its Pareto front, and the table, CSV and plot it is reported in.
#include <cstddef>
#include <string>
#include <vector>

namespace radview {

struct TradeoffRow {
  std::string method;                          // e.g. "clough-tocher"
  std::string setting;                         // "per pixel", "level 4", "adaptive 0.5", ...
  double frameMs = 0.0;                        // GPU time, median over frames
  size_t triangles = 0;                        // drawn or generated
  double rmse = 0.0, maxError = 0.0;           // luminance of B against the reference, radiometric
  double displayRmse = 0.0, displayMax = 0.0;  // displayed luminance, 8-bit steps
  double machBands = 0.0;  // mean gradient jump across untagged element edges, 8-bit steps per pixel
  double c0Kinks = 0.0;    // the same across edges tagged C0 (real kinks: a method should keep them)
  bool pareto = false;     // no other row is both faster and more accurate (display RMSE)
};

// Marks the rows on the front of (frameMs, displayRmse): no other row has both a lower or
// equal frame time and a lower or equal error, one of them strictly.
void markParetoFront(std::vector<TradeoffRow>& rows);

// A Markdown table of the rows (Pareto rows in bold), and the same as CSV with a header line.
std::string markdownTable(const std::vector<TradeoffRow>& rows);
std::string csvTable(const std::vector<TradeoffRow>& rows);

// Display RMSE against frame time (log scale) as a PNG: every row a dot, the Pareto front a
// line through its rows, labelled. `title` goes on top. Labels need a TrueType font
// (fonts-dejavu-core); without one the plot is drawn unlabelled and false is returned. Throws
// Error naming the path when it cannot be written.
bool writeTradeoffPlot(const std::vector<TradeoffRow>& rows, const std::string& title, const std::string& path);

}  // namespace radview
