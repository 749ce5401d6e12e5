#include "solve/radiosity_solve.h"

#include "discontinuity/contact_cut.h"
#include "mesh/uniform_mesher.h"

#include <cmath>

namespace radview {

double defaultPatchSize(const Scene& scene) {
  const double diagonal = scene.bounds().diagonal();
  return diagonal > 0.0 && std::isfinite(diagonal) ? diagonal / 12.0 : 1.0;
}

SolveSettings resolvedFor(const Scene& scene, SolveSettings settings) {
  if (!(settings.patchSize > 0.0)) settings.patchSize = defaultPatchSize(scene);
  if (!(settings.subdivision.minElementSize > 0.0)) settings.subdivision.minElementSize = settings.patchSize / 16.0;
  // A discontinuity mesh's triangles are far smaller than a patch near the shadow boundaries:
  // they shoot in groups of the patch size, and receive one by one.
  if (settings.discontinuityMeshing && !(settings.solver.shooterSize > 0.0))
    settings.solver.shooterSize = settings.patchSize;
  return settings;
}

RadiosityMesh initialMesh(const Scene& scene, const SolveSettings& resolved, DiscontinuityMeshReport* report) {
  return resolved.discontinuityMeshing ? meshWithDiscontinuities(scene, resolved.patchSize, report)
                                       : cutAtContacts(scene, meshUniformly(scene, resolved.patchSize));
}

RadiositySolve::RadiositySolve(const Scene& scene, const SolveSettings& settings, DiscontinuityMeshReport* report)
    : settings_(resolvedFor(scene, settings)),
      solver_(std::make_unique<ProgressiveRefinement>(scene, initialMesh(scene, settings_, report), settings_.solver)) {
  std::vector<SolveView>& views = settings_.subdivision.views;
  if (views.empty()) return;
  UsableViews usable = usableViews(solver_->solution(false), views);
  views = std::move(usable.views);
  viewWarnings_ = std::move(usable.warnings);
  if (views.empty()) viewWarnings_.push_back("no view sees the scene: the subdivision is view-independent");
}

bool RadiositySolve::step() {
  if (phase_ == Phase::Shooting) {
    // Bounded by maxShots (the solver is finished once it is reached).
    if (solver_->step()) return true;
    phase_ = settings_.subdivide ? Phase::Subdividing : Phase::Done;
    return phase_ != Phase::Done;
  }
  if (phase_ == Phase::Subdividing) {
    const size_t split = rounds_ < settings_.maxRounds ? solver_->subdivide(settings_.subdivision) : 0;
    if (split > 0) {
      ++rounds_;
      split_ += split;
      return true;
    }
    // The subdivided elements' own radiosities left light unshot (ProgressiveRefinement::
    // subdivide): shoot it, then look again for elements to split.
    if (!solver_->finished()) {
      phase_ = Phase::Shooting;
      return true;
    }
    phase_ = Phase::Done;
  }
  return false;
}

SolveSummary RadiositySolve::summary() const {
  SolveSummary summary;
  summary.progress = solver_->progress();
  summary.subdivisionRounds = rounds_;
  summary.elementsSplit = split_;
  summary.ignoredPolygons = solver_->ignoredPolygons();
  summary.energy = solver_->energyBalance();
  summary.views = settings_.subdivision.views.size();
  summary.viewWarnings = viewWarnings_;
  return summary;
}

RadiosityMesh solveRadiosity(const Scene& scene, const SolveSettings& settings, SolveSummary& summary,
                             const std::function<void(const SolveProgress&)>& report,
                             DiscontinuityMeshReport* discontinuities) {
  RadiositySolve solve(scene, settings, discontinuities);
  while (solve.step())
    if (report) report(solve.progress());
  summary = solve.summary();
  return solve.solution();
}

}  // namespace radview
