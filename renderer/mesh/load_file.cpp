#include "mesh/load_file.h"

#include "mesh/solution_file.h"
#include "scene/gltf_document.h"
#include "scene/gltf_import.h"
#include "scene/quad_merge.h"

namespace radview {

LoadedFile loadFile(const std::string& path) {
  const GltfDocument document(path);
  LoadedFile loaded;
  loaded.path = path;
  loaded.warnings = document.warnings();
  loaded.isSolution = isSolution(document);
  if (loaded.isSolution) {
    loaded.mesh = readSolution(document);
    loaded.scene.cameras = importCameras(document, loaded.warnings);
  } else {
    loaded.scene = mergeTrianglesIntoQuads(importScene(document, loaded.warnings));
  }
  return loaded;
}

}  // namespace radview
