#include "app/scene_light.h"

#include "core/limits.h"

namespace radview {

void addSolverOptions(CLI::App& command, SolveSettings& s) {
  command
      .add_option("--samples", s.solver.samples,
                  "Solve: shooter samples per node and shot, one stratified batch (more where the shooter is seen "
                  "in part: --max-samples)")
      ->check(CLI::Range(1, kMaxSolverSamples))
      ->capture_default_str();
  command
      .add_option("--max-samples", s.solver.maxSamples,
                  "Solve: a node that sees a shooter in part takes more batches of --samples, up to this many "
                  "samples, until --visibility-error is met; at most --samples: every node takes --samples")
      ->check(CLI::Range(1, kMaxSolverSamples))
      ->capture_default_str();
  command
      .add_option("--visibility-error", s.solver.visibilityError,
                  "Solve: the standard error of a partly visible shooter's visible fraction that ends its sampling "
                  "(with --max-samples)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  command
      .add_option("--unshot", s.solver.stopUnshotFraction,
                  "Solve: stop once the unshot power is this fraction of the emitted power")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  command.add_option("--max-shots", s.solver.maxShots, "Solve: stop after this many shots in any case")
      ->check(CLI::Range(size_t(1), kMaxSolverShots))
      ->capture_default_str();
  command.add_option("--max-elements", s.subdivision.maxElements, "Solve: subdivision stops at this many elements")
      ->check(CLI::Range(size_t(1), kMaxMeshElements))
      ->capture_default_str();
  command
      .add_option("--interpolation-error", s.subdivision.relativeError,
                  "Solve: subdivision also splits elements where linear interpolation is off by more than this "
                  "fraction of B at their centre (estimated by Clough-Tocher there; of 1 % of display white where B "
                  "is darker); 0: off (the spread criterion, --tolerance, alone). With --unshot 0.0005, 0.005 "
                  "converges the mesh: the Cornell box within 0.5 % of the truth with discontinuity meshing")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  command
      .add_flag("--discontinuity-meshing,!--no-discontinuity-meshing", s.discontinuityMeshing,
                "Solve: patches from discontinuity meshing (Heckbert 1992; Lischinski et al. 1992): each polygon a "
                "constrained Delaunay mesh through the shadow boundaries its emitters cast, contact lines tagged "
                "C-1, D1 boundaries C0; its triangles shoot in groups of the patch size")
      ->capture_default_str();
}

void addSceneLightOptions(CLI::App& command, SceneLightOptions& options) {
  command.add_flag("--direct-only", options.directOnly,
                   "Scenes: light by the emitters' direct light alone, unoccluded, instead of solving (a quick "
                   "preview: no shadows, no interreflection)");
  addSolverOptions(command, options.solve);
}

}  // namespace radview
