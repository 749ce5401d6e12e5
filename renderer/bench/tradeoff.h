#pragma once
// The speed-versus-accuracy trade of radview's methods, as `radview bench` measures it: one
// row per method and setting, its Pareto front, and the table, CSV and plot it is reported in.
#include "bench/error_estimate.h"

#include <cstddef>
#include <string>
#include <vector>

namespace radview {

struct TradeoffRow {
  std::string method;    // e.g. "clough-tocher"
  std::string setting;   // "per pixel", "level 4", "adaptive 0.5", ...
  double frameMs = 0.0;  // GPU time, median over frames
  size_t triangles = 0;  // drawn or generated
  // Against the reference image as it is (the mean of its runs, noise and all):
  double rmse = 0.0, maxError = 0.0;           // luminance of B, radiometric
  double displayRmse = 0.0, displayMax = 0.0;  // displayed luminance, 8-bit steps
  double machBands = 0.0;  // mean gradient jump across untagged element edges, 8-bit steps per pixel
  double c0Kinks = 0.0;    // the same across edges tagged C0 (real kinks: a method should keep them)
  // Against what the reference converges to, its noise taken out, with 95 % intervals
  // (bench/error_estimate.h): luminance of B, displayed luminance (steps), and the gradient
  // jumps across untagged and C0 edges against the reference's own (steps per pixel).
  ErrorEstimate linearError, displayError, machError, c0KinkError;
  double referenceNoiseRmse = 0.0, referenceNoiseSteps = 0.0;  // the reference image's, every row alike
  // Per pixel rows: the display error split into the solution's part and the reconstruction's
  // (bench/nodal_reference.h), when `split`.
  ErrorEstimate solutionPart, reconstructionPart;
  double nodeNoiseSteps = 0.0;  // the noise the drawn nodal values carry (ErrorSplit)
  bool split = false;
  std::string image;    // the row's linear image in the output folder (its file name)
  bool pareto = false;  // no other row is both faster and more accurate (displayError's estimate)
};

// Marks the rows on the front of (frameMs, displayError.rms()): no other row has both a lower or
// equal frame time and a lower or equal error, one of them strictly.
void markParetoFront(std::vector<TradeoffRow>& rows);

// A file name for the row's outputs, without extension: "clough-tocher-level-4",
// "c1-quadratic-per-pixel-c0-not-relaxed".
std::string rowFileStem(const TradeoffRow& row);

// The per-pixel rows (setting "per pixel") grouped by their display errors' intervals: one
// line per row, naming the rows it ties with (intervals overlap) and those it is better than.
std::string tieReport(const std::vector<TradeoffRow>& rows);
// The split rows' error, solution's part and reconstruction's part as a Markdown table, then
// the ties of the reconstruction's part as tieReport gives them; empty when no row is split.
std::string splitReport(const std::vector<TradeoffRow>& rows);

// A figure to 3 significant digits (or `digits`), as the tables print it.
std::string number(double v, int digits = 3);
// "2.37 [2.35, 2.39]": an estimate's root mean square and its 95 % interval; the value alone
// against an exact reference.
std::string withInterval(const ErrorEstimate& e);

// A Markdown table of the rows (Pareto rows in bold), and the same as CSV with a header line.
std::string markdownTable(const std::vector<TradeoffRow>& rows);
std::string csvTable(const std::vector<TradeoffRow>& rows);

// The display error estimate against frame time (log scale) as a PNG: every row a dot with its
// 95 % interval as a bar, the Pareto front a line through its rows, labelled; a grey band is the
// best row's interval, so a bar that reaches into it is a tie with the best. `title` goes on top. Labels need a
// TrueType font (fonts-dejavu-core); without one the plot is drawn unlabelled and false is returned. Throws Error
// naming the path when it cannot be written.
bool writeTradeoffPlot(const std::vector<TradeoffRow>& rows, const std::string& title, const std::string& path);

}  // namespace radview
