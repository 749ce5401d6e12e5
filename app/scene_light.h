#pragma once
// The command-line options that say how a scene is lit when it is opened to be drawn, sampled or
// measured (solve/viewed_file.h's SceneLightOptions).
#include "solve/viewed_file.h"

#include <CLI/CLI.hpp>

namespace radview {

// The solve's options that no other command uses for something else: --samples, --unshot,
// --max-shots, --max-elements, --interpolation-error, --discontinuity-meshing /
// --no-discontinuity-meshing.
void addSolverOptions(CLI::App& command, SolveSettings& settings);
// --direct-only and addSolverOptions, for the commands that open scenes to draw or measure them.
void addSceneLightOptions(CLI::App& command, SceneLightOptions& options);

}  // namespace radview
