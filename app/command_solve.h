#pragma once
// radview solve: a scene in, a radiosity solution file out (progressive refinement with
// adaptive subdivision, renderer/solve/radiosity_solve.h).
#include "solve/discontinuity_mesher.h"
#include "solve/radiosity_solve.h"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

namespace radview {

struct SolveOptions {
  std::string file;
  std::string out;
  double elementSize = 0.0;     // patch size of the initial uniform mesh; 0: bounds diagonal / 12
  double minElementSize = 0.0;  // 0: the patch size / 16
  size_t maxElements = 20000;
  double tolerance = 8.0;       // subdivision: display spread, in 8-bit steps
  bool quadratic = false;
  bool triangulateTVertices = false;
  uint64_t seed = 1;
  int samples = 16;
  double unshot = 0.01;
  size_t maxShots = 100000;
  bool noAmbient = false;
  bool discontinuityMeshing = false;  // patches from meshWithDiscontinuities, not the uniform mesher
};

CLI::App* addSolveCommand(CLI::App& app, SolveOptions& options);
// Shared with the viewer's background solve, so both solve alike.
// Patches of a scene, unless --element-size says: bounds diagonal / 12.
double patchSizeFor(const SolveOptions& options, const Scene& scene);
SolveSettings solveSettingsFrom(const SolveOptions& options, double patchSize);
// The patches: meshUniformly's, or meshWithDiscontinuities' (`report` may be null). Throws Error.
RadiosityMesh initialMesh(const SolveOptions& options, const Scene& scene, DiscontinuityMeshReport* report);
int runSolve(const SolveOptions& options);

}  // namespace radview
