#pragma once
// A file as the viewer and the commands show it: a solution file as it is, or a scene solved as
// `radview solve` solves it, or (a preview, --direct-only) meshed uniformly and lit by its
// emitters' unoccluded direct light.
#include "import/load_file.h"
#include "mesh/radiosity_mesh.h"
#include "solve/radiosity_solve.h"

#include <functional>
#include <string>

namespace radview {

// How a scene (a file that holds no solution) is lit when it is opened to be drawn, sampled or
// measured: solved, the light it has (the default), or by its emitters' direct light alone.
struct SceneLightOptions {
  bool directOnly = false;
  SolveSettings solve;  // radview solve's defaults
};

// Light by the emitters' direct light alone (what the viewer shows until its solve publishes).
inline const SceneLightOptions kDirectLight = [] {
  SceneLightOptions light;
  light.directOnly = true;
  return light;
}();

// The words that say how a scene was lit by --direct-only, for output and the panel.
inline constexpr const char* kDirectOnlyLabel =
    "direct light only (--direct-only preview: no shadows, no interreflection)";

struct ViewedFile {
  LoadedFile file;           // its mesh moved into `mesh`
  RadiosityMesh mesh;        // what is drawn
  double elementSize = 0.0;  // for scenes: the uniform mesh's element size, or the solve's patches'; 0 for solutions
  std::string lighting;          // for scenes: how they were lit, in words (a solve's summary, or kDirectOnlyLabel)
  bool directLightOnly = false;  // a scene lit by --direct-only: it has no solution to gather from
};

// Called as a scene's solve goes on, and once more with `finished` true when it is done.
using SolveProgressCallback = std::function<void(const SolveProgress&, bool finished)>;

// elementSize <= 0 picks the default (defaultElementSize(scene), or the solve's patch size);
// `import` says how another tool's mesh is read (import/load_file.h); `light` how a scene is lit.
// `checkLoaded`, if given, sees the file once it is read and before a scene is meshed or solved:
// options that depend on the file (a camera) are refused there, not after a solve. Every error
// names the file. Throws Error.
ViewedFile openForViewing(const std::string& path, double elementSize, const ImportOptions& import,
                          const SceneLightOptions& light,
                          const std::function<void(const LoadedFile&)>& checkLoaded = nullptr,
                          const SolveProgressCallback& onProgress = nullptr);

}  // namespace radview
