#pragma once
// How a scene (a glTF file that holds no solution) is lit when it is opened to be drawn, sampled
// or measured: solved as `radview solve` solves it, the light it has (the default), or lit by
// its emitters' direct light alone with no occlusion (--direct-only: a quick preview with no
// shadows and no interreflection, labelled so wherever it is shown).
#include "solve/radiosity_solve.h"

#include <CLI/CLI.hpp>

namespace radview {

struct SceneLightOptions {
  bool directOnly = false;
  SolveSettings solve;  // radview solve's defaults; the options bind to its fields
};

// The solve's options that no other command uses for something else: --samples, --unshot,
// --max-shots, --max-elements, --discontinuity-meshing / --no-discontinuity-meshing.
void addSolverOptions(CLI::App& command, SolveSettings& settings);
// --direct-only and addSolverOptions, for the commands that open scenes to draw or measure them.
void addSceneLightOptions(CLI::App& command, SceneLightOptions& options);

// Light by the emitters' direct light alone (what the viewer shows until its solve publishes).
inline const SceneLightOptions kDirectLight = [] {
  SceneLightOptions light;
  light.directOnly = true;
  return light;
}();

// The words that say how a scene was lit, for output and the panel: "direct light only
// (--direct-only preview: no shadows, no interreflection)".
inline constexpr const char* kDirectOnlyLabel = "direct light only (--direct-only preview: no shadows, no interreflection)";

}  // namespace radview
