#pragma once
// The solve's progress on a terminal: `radview solve`, and the solve that render, bench, sample
// and export run when they open a scene.
#include "solve/progressive_refinement.h"
#include "solve/viewed_file.h"

#include <chrono>
#include <string>

namespace radview {

// 1234567 -> "1.23M": a count to about three digits.
std::string humanCount(double n);

// One line on a terminal, redrawn in place at most 10 times a second. The bar fills as the
// unshot fraction falls from 1 to the stop fraction, on a log scale (progressive refinement
// removes a roughly constant factor per sweep of shots).
class ProgressBar {
 public:
  ProgressBar(bool enabled, double stopFraction) : enabled_(enabled), stop_(stopFraction) {}
  void update(const SolveProgress& p, bool force = false);
  void finish();

 private:
  bool enabled_;
  double stop_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_{};
};

// The bar for the solve of a scene that openForViewing runs with `light`, on standard error when
// that is a terminal (nothing otherwise).
SolveProgressCallback solveProgressOnTerminal(const SceneLightOptions& light);

}  // namespace radview
