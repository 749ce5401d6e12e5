#include "app/solve_progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace radview {

std::string humanCount(double n) {
  char text[32];
  if (n >= 1e9)
    std::snprintf(text, sizeof text, "%.2fG", n / 1e9);
  else if (n >= 1e6)
    std::snprintf(text, sizeof text, "%.2fM", n / 1e6);
  else if (n >= 1e3)
    std::snprintf(text, sizeof text, "%.1fk", n / 1e3);
  else
    std::snprintf(text, sizeof text, "%.0f", n);
  return text;
}

void ProgressBar::update(const SolveProgress& p, bool force) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (!force && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  const double done = p.unshotFraction <= stop_ || stop_ <= 0.0
                          ? 1.0
                          : std::clamp(std::log(std::max(p.unshotFraction, 1e-300)) / std::log(stop_), 0.0, 1.0);
  const int width = 24, filled = int(std::lround(done * width));
  std::fprintf(stderr, "\r[%s%s] shots %zu  unshot %.2f%%  elements %zu  nodes %zu  %s rays/s ",
               std::string(filled, '#').c_str(), std::string(width - filled, ' ').c_str(), p.shots,
               100.0 * p.unshotFraction, p.elements, p.nodes, humanCount(p.raysPerSecond()).c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressBar::finish() {
  if (drawn_) std::fprintf(stderr, "\n");
}

SolveProgressCallback solveProgressOnTerminal(const SceneLightOptions& light) {
  auto bar = std::make_shared<ProgressBar>(isatty(fileno(stderr)) != 0, light.solve.solver.stopUnshotFraction);
  return [bar](const SolveProgress& p, bool finished) {
    bar->update(p, finished);
    if (finished) bar->finish();
  };
}

}  // namespace radview
