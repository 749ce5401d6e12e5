#include "solve/viewed_file.h"

#include "core/error.h"
#include "mesh/topology.h"
#include "solve/direct_light.h"

#include <chrono>
#include <cstdio>
#include <string>

namespace radview {

namespace {

// The scene solved with `given`'s settings; `lighting` says how, in words.
RadiosityMesh solvedScene(const Scene& scene, double elementSize, const SolveSettings& given,
                          const SolveProgressCallback& onProgress, std::string& lighting, double& patchSize) {
  SolveSettings settings = given;
  if (elementSize > 0.0) settings.patchSize = elementSize;
  settings = resolvedFor(scene, settings);
  SolveSummary summary;
  const auto start = std::chrono::steady_clock::now();
  RadiosityMesh mesh = solveRadiosity(scene, settings, summary, [&](const SolveProgress& p) {
    if (onProgress) onProgress(p, false);
  });
  if (onProgress) onProgress(summary.progress, true);
  const SolveProgress& p = summary.progress;
  char text[256];
  std::snprintf(text, sizeof text, "radiosity solve%s: %zu shots, %.2f%% unshot, %zu elements, %.1f s",
                settings.discontinuityMeshing ? " with discontinuity meshing" : "", p.shots, 100.0 * p.unshotFraction,
                mesh.elements.size(), std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  lighting = text;
  patchSize = settings.patchSize;
  return mesh;
}

}  // namespace

ViewedFile openForViewing(const std::string& path, double elementSize, const ImportOptions& import,
                          const SceneLightOptions& light, const std::function<void(const LoadedFile&)>& checkLoaded,
                          const SolveProgressCallback& onProgress) {
  ViewedFile viewed;
  viewed.file = loadFile(path, import);
  if (checkLoaded) checkLoaded(viewed.file);
  // Meshing, lighting and topology report problems without knowing the file: name it here,
  // so every error the user sees says which file it is about.
  try {
    if (viewed.file.isSolution) {
      viewed.mesh = std::move(viewed.file.mesh);  // one copy, not two
      viewed.file.mesh = {};
    } else if (light.directOnly) {
      viewed.elementSize = elementSize > 0.0 ? elementSize : defaultElementSize(viewed.file.scene);
      viewed.mesh = meshAndLight(viewed.file.scene, viewed.elementSize);
      viewed.lighting = kDirectOnlyLabel;
      viewed.directLightOnly = true;
    } else {
      viewed.mesh =
          solvedScene(viewed.file.scene, elementSize, light.solve, onProgress, viewed.lighting, viewed.elementSize);
    }
    checkDiscontinuityEdges(viewed.mesh);
  } catch (const Error& e) {
    const std::string what = e.what();
    throw what.rfind(path + ": ", 0) == 0 ? e : Error(path, what);
  }
  return viewed;
}

}  // namespace radview
