#include "import/load_file.h"

#include "core/error.h"
#include "core/input_file.h"
#include "core/strings.h"
#include "import/assimp_mesh.h"
#include "import/gltf_colour_mesh.h"
#include "import/ply_mesh.h"
#include "mesh/solution_file.h"
#include "scene/gltf_document.h"
#include "scene/gltf_import.h"
#include "scene/quad_merge.h"

namespace radview {

namespace {

void takeImported(LoadedFile& loaded, ImportedMesh&& imported, const ImportOptions& options) {
  assumeMaterials(imported, options, loaded.path);
  loaded.isSolution = true;
  loaded.mesh = std::move(imported.mesh);
  loaded.valueSource = std::move(imported.valueSource);
  loaded.gatherRefusal = std::move(imported.gatherRefusal);
  loaded.warnings.insert(loaded.warnings.end(), imported.warnings.begin(), imported.warnings.end());
}

}  // namespace

LoadedFile loadFile(const std::string& path, const ImportOptions& options) {
  LoadedFile loaded;
  loaded.path = path;
  const std::string ext = lowerExtension(path);
  if (ext == ".ply") {
    takeImported(loaded, readPlyMesh(path, options), options);
    return loaded;
  }
  if (ext != ".gltf" && ext != ".glb" && assimpReads(path)) {
    takeImported(loaded, readAssimpMesh(path, options), options);
    return loaded;
  }
  if (ext != ".gltf" && ext != ".glb") {
    checkInputFile(path, "a mesh file");
    throw Error(path, "unknown file type \"" + ext + "\" (radview reads .gltf, .glb, .ply, .obj and Assimp's formats)");
  }
  const GltfDocument document(path);
  loaded.warnings = document.warnings();
  loaded.isSolution = isSolution(document);
  if (loaded.isSolution) {
    loaded.mesh = readSolution(document);
    loaded.scene.cameras = importCameras(document, loaded.warnings);
  } else if (options.readAs != ReadAs::Scene && (hasVertexColours(document) || options.readAs == ReadAs::Solution)) {
    if (!hasVertexColours(document)) throw Error(path, "--read-as solution: no primitive has COLOR_0");
    ColourMeshReading reading = readColourMesh(document, options);
    if (reading.isMesh) {
      takeImported(loaded, std::move(reading.imported), options);
      loaded.scene.cameras = std::move(reading.scene.cameras);
    } else {
      loaded.warnings.insert(loaded.warnings.end(), reading.imported.warnings.begin(), reading.imported.warnings.end());
      loaded.scene = mergeTrianglesIntoQuads(std::move(reading.scene));
    }
  } else {
    loaded.scene = mergeTrianglesIntoQuads(importScene(document, loaded.warnings));
  }
  return loaded;
}

}  // namespace radview
