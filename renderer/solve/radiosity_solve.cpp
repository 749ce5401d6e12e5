#include "solve/radiosity_solve.h"

namespace radview {

RadiosityMesh solveRadiosity(const Scene& scene, RadiosityMesh initial, const SolveSettings& settings,
                             SolveSummary& summary, const std::function<void(const SolveProgress&)>& report) {
  ProgressiveRefinement solver(scene, std::move(initial), settings.solver);
  // Bounded by maxShots (finished() is true once it is reached).
  while (solver.step())
    if (report) report(solver.progress());
  summary = SolveSummary{};
  if (settings.subdivide)
    for (; summary.subdivisionRounds < settings.maxRounds; ++summary.subdivisionRounds) {
      const size_t split = solver.subdivide(settings.subdivision);
      if (split == 0) break;
      summary.elementsSplit += split;
      if (report) report(solver.progress());
    }
  summary.progress = solver.progress();
  summary.ignoredPolygons = solver.ignoredPolygons();
  summary.energy = solver.energyBalance();
  return solver.solution(settings.ambient);
}

}  // namespace radview
