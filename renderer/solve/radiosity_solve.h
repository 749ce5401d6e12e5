#pragma once
// The whole solve: progressive refinement to the stop criterion, then rounds of adaptive
// subdivision, each valuing its new nodes by replaying the shots, until nothing splits.
#include "mesh/radiosity_mesh.h"
#include "scene/scene.h"
#include "solve/adaptive_subdivision.h"
#include "solve/progressive_refinement.h"

#include <functional>

namespace radview {

struct SolveSettings {
  SolverSettings solver;
  SubdivisionCriteria subdivision;
  bool subdivide = true;
  // Rounds of subdivision at most: each halves the smallest elements, so with a minimum
  // element size this bound is never reached in practice; it keeps every solve finite.
  int maxRounds = 16;
  bool ambient = true;  // add the ambient term to the values returned (display only)
};

struct SolveSummary {
  SolveProgress progress;
  int subdivisionRounds = 0;
  size_t elementsSplit = 0;
  size_t ignoredPolygons = 0;
  EnergyBalance energy;
};

// Calls `report` (if set) after every shot and every subdivision round. Throws Error as
// ProgressiveRefinement does.
RadiosityMesh solveRadiosity(const Scene& scene, RadiosityMesh initial, const SolveSettings& settings,
                             SolveSummary& summary,
                             const std::function<void(const SolveProgress&)>& report = nullptr);

}  // namespace radview
