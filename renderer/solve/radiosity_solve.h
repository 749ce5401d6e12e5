#pragma once
// The whole solve: progressive refinement to the stop criterion, then rounds of adaptive
// subdivision, each valuing its new nodes by replaying the shots, until nothing splits; then
// the light the subdivision left unshot is shot to the stop criterion, and the rounds go on,
// until a round splits nothing with the criterion met.
// RadiositySolve takes it one step at a time, so that `radview solve` and the viewer's
// background solve (solve/background_solve.h) run the same steps; solveRadiosity runs them all.
#include "discontinuity/discontinuity_mesher.h"
#include "mesh/radiosity_mesh.h"
#include "scene/scene.h"
#include "solve/adaptive_subdivision.h"
#include "solve/progressive_refinement.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace radview {

struct SolveSettings {
  // Edge length of the patches, the initial mesh; 0: defaultPatchSize(scene).
  double patchSize = 0.0;
  // Patches from discontinuity meshing (meshWithDiscontinuities) rather than a uniform mesh;
  // its triangles then shoot in groups of the patch size.
  bool discontinuityMeshing = false;
  SolverSettings solver;
  // Its minElementSize 0: the patch size / 16.
  SubdivisionCriteria subdivision;
  bool subdivide = true;
  // Rounds of subdivision at most: each halves the smallest elements, so with a minimum
  // element size this bound is never reached in practice; it keeps every solve finite.
  int maxRounds = 16;
  bool ambient = true;  // add the ambient term to the values returned (display only)
};

// Patches of a scene by default: its bounds' diagonal / 12 (the Cornell box: about 80 mm, 340
// patches). Shooting costs patches x nodes, so patches are kept coarse; subdivision refines
// the receiving elements under them (Cohen et al. 1986).
double defaultPatchSize(const Scene& scene);

// `settings` with the defaults that depend on the scene filled in: the patch size, the
// smallest element, the shooters of a discontinuity mesh.
SolveSettings resolvedFor(const Scene& scene, SolveSettings settings);

// The patches: meshUniformly's cut along the lines where polygons touch (cutAtContacts), or
// meshWithDiscontinuities' (`report` may be null), for resolved settings. Throws Error.
RadiosityMesh initialMesh(const Scene& scene, const SolveSettings& resolved, DiscontinuityMeshReport* report);

struct SolveSummary {
  SolveProgress progress;
  int subdivisionRounds = 0;
  size_t elementsSplit = 0;
  size_t ignoredPolygons = 0;
  EnergyBalance energy;
  // The views the subdivision meshed for (SubdivisionCriteria::views), and a line for each view
  // given that sees nothing of the scene from the front and was left out.
  size_t views = 0;
  std::vector<std::string> viewWarnings;
};

class RadiositySolve {
 public:
  enum class Phase { Shooting, Subdividing, Done };

  // Meshes the scene (initialMesh) and sets up the shooting. Views of the subdivision criteria
  // that see no element's front side are left out (summary().viewWarnings says which); when none
  // is left, the subdivision is view-independent. Throws Error as ProgressiveRefinement does.
  RadiositySolve(const Scene& scene, const SolveSettings& settings, DiscontinuityMeshReport* report = nullptr);

  // One shot while shooting, else one round of subdivision (the call that finds nothing left
  // to shoot only moves on to subdividing, and the round that splits nothing goes back to
  // shooting if the subdivision left light unshot); false once the solve is done.
  bool step();
  Phase phase() const { return phase_; }
  const SolveSettings& settings() const { return settings_; }
  const SolveProgress& progress() const { return solver_->progress(); }
  // The nodal radiosities so far (with the ambient term when the settings say so).
  RadiosityMesh solution() const { return solver_->solution(settings_.ambient); }
  SolveSummary summary() const;

 private:
  SolveSettings settings_;
  std::unique_ptr<ProgressiveRefinement> solver_;
  Phase phase_ = Phase::Shooting;
  int rounds_ = 0;
  size_t split_ = 0;
  std::vector<std::string> viewWarnings_;
};

// Every step of a RadiositySolve; `report` (if set) after every shot and subdivision round.
RadiosityMesh solveRadiosity(const Scene& scene, const SolveSettings& settings, SolveSummary& summary,
                             const std::function<void(const SolveProgress&)>& report = nullptr,
                             DiscontinuityMeshReport* discontinuities = nullptr);

}  // namespace radview
