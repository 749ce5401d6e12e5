#include "app/command_solve.h"

#include "app/commands.h"
#include "app/scene_light.h"
#include "app/solve_progress_bar.h"
#include "core/camera.h"
#include "core/strings.h"

#include "core/error.h"
#include "core/limits.h"
#include "core/parallel_for.h"
#include "discontinuity/discontinuity_mesher.h"
#include "import/load_file.h"
#include "interp/t_vertex_repair.h"
#include "mesh/solution_file.h"
#include "mesh/topology.h"
#include "mesh/uniform_mesher.h"
#include "scene/camera_presets.h"
#include "solve/radiosity_solve.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace radview {

namespace {

using Clock = std::chrono::steady_clock;

// The views --view names, each looked at with --view-size pixels. Throws Error naming the option.
std::vector<SolveView> solveViews(const SolveOptions& options, const Scene& scene) {
  std::vector<SolveView> views;
  if (options.views.empty()) return views;
  int width = 0, height = 0;
  parseSize(options.viewSize, width, height, "--view-size");
  for (const std::string& spec : options.views) {
    if (spec == "file") {
      if (scene.cameras.empty()) throw Error(options.file, "--view file: the scene has no camera");
      for (const SceneCamera& camera : scene.cameras)
        views.push_back({cameraFromSpec("file", scene.bounds(), {camera}), width, height,
                         camera.name.empty() ? "file" : camera.name});
      continue;
    }
    try {
      views.push_back({cameraFromSpec(spec, scene.bounds(), scene.cameras), width, height, spec});
    } catch (const Error& e) {
      // cameraFromSpec names the option it serves most often, --camera.
      std::string reason = e.what();
      if (reason.rfind("--camera", 0) == 0) reason.replace(0, 8, "--view");
      throw Error(reason);
    }
  }
  return views;
}

}  // namespace

CLI::App* addSolveCommand(CLI::App& app, SolveOptions& o) {
  CLI::App* command = app.add_subcommand(
      "solve",
      "Solve SCENE's radiosity (progressive refinement, Embree visibility, adaptive subdivision with "
      "T-vertices) and write a solution file");
  command->add_option("file", o.file, "A glTF scene (.gltf/.glb)")->required();
  command->add_option("--out,-o", o.out, "The solution file to write (.glb or .gltf)")->required();
  command
      ->add_option("--element-size", o.settings.patchSize,
                   "Edge length of the patches, the initial uniform mesh (default: bounds diagonal / 12)")
      ->check(CLI::Range(1e-12, 1e12));
  command
      ->add_option("--min-element-size", o.settings.subdivision.minElementSize,
                   "Subdivision splits no element below this size (default: the patch size / 16)")
      ->check(CLI::Range(1e-12, 1e12));
  command
      ->add_option("--tolerance", o.settings.subdivision.tolerance,
                   "Subdivision splits elements whose nodal values differ by more than this on display, in 8-bit "
                   "steps of the tone-mapped, sRGB-encoded luminance")
      ->check(CLI::Range(0.01, 255.0))
      ->capture_default_str();
  command->add_flag("--balance", o.settings.subdivision.balance,
                    "2:1 balance: also split elements until neighbours differ by at most one level (no element edge "
                    "holds more than one T-vertex)");
  command
      ->add_option("--view", o.views,
                   "Mesh for this view (C&W 9.3), repeatable: a preset (" + joined(cameraPresetNames()) +
                       "), ex,ey,ez/tx,ty,tz[/ux,uy,uz], or 'file' for each of the scene's cameras. Subdivision "
                       "then splits only elements the views see, those whose error shows on most pixels first")
      ->type_name("CAMERA");
  command->add_option("--view-size", o.viewSize, "The pixels each --view is looked at with, WIDTHxHEIGHT")
      ->capture_default_str();
  command->add_flag("--quadratic", o.settings.solver.quadratic,
                    "Quadratic elements: nodes at the middle of every edge too");
  command->add_flag("--triangulate-t-vertices", o.triangulateTVertices,
                    "Cut every element with a T-vertex into triangles through it (Baum et al.) before writing");
  command->add_option("--seed", o.settings.solver.seed, "Seed of the shooter sampling (same seed, same solution)")
      ->capture_default_str();
  addSolverOptions(*command, o.settings);
  command->add_flag("--no-ambient", o.noAmbient,
                    "Write the solution without the ambient term (where the light not yet shot would go)");
  return command;
}

int runSolve(const SolveOptions& options) {
  const auto start = Clock::now();
  LoadedFile file = loadFile(options.file);
  if (file.isSolution && !file.valueSource.empty())
    throw Error(options.file, "is a radiosity mesh (B from " + file.valueSource + "); solve takes a glTF scene");
  if (file.isSolution) throw Error(options.file, "is a solution file already; solve takes a scene");
  for (const std::string& w : file.warnings) std::fprintf(stderr, "radview: warning: %s\n", w.c_str());
  const Scene& scene = file.scene;
  SolveSettings settings = options.settings;
  settings.ambient = !options.noAmbient;
  settings.subdivision.views = solveViews(options, scene);
  settings = resolvedFor(scene, settings);

  ProgressBar bar(isatty(fileno(stderr)) != 0, settings.solver.stopUnshotFraction);
  SolveSummary summary;
  DiscontinuityMeshReport discontinuities;
  RadiosityMesh mesh;
  try {
    mesh = solveRadiosity(
        scene, settings, summary, [&](const SolveProgress& p) { bar.update(p); }, &discontinuities);
  } catch (const Error& e) {
    bar.finish();
    throw Error(options.file, e.what());
  }
  bar.update(summary.progress, true);
  bar.finish();
  for (const std::string& w : summary.viewWarnings) std::fprintf(stderr, "radview: warning: %s\n", w.c_str());
  size_t repaired = 0;
  if (options.triangulateTVertices) mesh = repairTVertices(mesh, &repaired);
  writeSolution(mesh, options.out, scene.cameras);

  const MeshTopology topology(mesh);
  const SolveProgress& p = summary.progress;
  const EnergyBalance& energy = summary.energy;
  const double emitted = energy.emitted.r + energy.emitted.g + energy.emitted.b;
  const double absorbed = energy.absorbed.r + energy.absorbed.g + energy.absorbed.b;
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::printf("solved %s -> %s\n", options.file.c_str(), options.out.c_str());
  std::printf("patches: %zu (size %g); elements: %zu %s; nodes: %zu; T-vertices: %zu\n", p.patches, settings.patchSize,
              mesh.elements.size(), settings.solver.quadratic ? "quadratic" : "linear", mesh.nodes.size(),
              topology.tVertices().size());
  char interpolationError[64] = "";
  if (settings.subdivision.relativeError > 0.0)
    std::snprintf(interpolationError, sizeof interpolationError, ", interpolation error %g %%",
                  100.0 * settings.subdivision.relativeError);
  std::printf("subdivision: %d rounds, %zu elements split (tolerance %g steps%s, min size %g, max %zu elements%s)\n",
              summary.subdivisionRounds, summary.elementsSplit, settings.subdivision.tolerance, interpolationError,
              settings.subdivision.minElementSize, settings.subdivision.maxElements,
              settings.subdivision.balance ? ", 2:1 balanced" : "");
  if (summary.views > 0)
    std::printf("meshed for %zu view%s at %s (elements no view sees are not split)\n", summary.views,
                summary.views == 1 ? "" : "s", options.viewSize.c_str());
  if (settings.discontinuityMeshing) std::cout << discontinuities << "\n" << std::flush;
  std::printf("discontinuity edges: C-1 %zu, C0 %zu\n", topology.countEdges(Continuity::Cm1),
              topology.countEdges(Continuity::C0));
  if (options.triangulateTVertices) std::printf("T-vertex triangulation: %zu elements cut into triangles\n", repaired);
  std::printf("shots: %zu; unshot: %.3f%% of the emitted power; absorbed: %.2f%% of it\n", p.shots,
              100.0 * p.unshotFraction, emitted > 0.0 ? 100.0 * absorbed / emitted : 0.0);
  std::printf("rays: %s, %s rays/s on %u threads\n", humanCount(double(p.rays)).c_str(),
              humanCount(p.raysPerSecond()).c_str(), workerCount());
  if (summary.ignoredPolygons > 0) std::printf("ignored: %zu zero-area polygons\n", summary.ignoredPolygons);
  std::printf("time: %.2f s (form factors %.2f s)\n", seconds, p.seconds);
  return 0;
}

}  // namespace radview
