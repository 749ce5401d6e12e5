#pragma once
// The one entry point that opens whatever the user names: a glTF scene to solve, a radview
// solution file (glTF with the RADVIEW_radiosity_mesh extension) to view, or another tool's
// mesh with per-vertex values (PLY, OBJ and Assimp's other formats, glTF with COLOR_0).
#include "import/import_options.h"
#include "mesh/radiosity_mesh.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace radview {

struct LoadedFile {
  std::string path;
  bool isSolution = false;            // a radiosity mesh: radview's own or imported
  Scene scene;                        // the imported scene, quads merged; a solution's cameras only
  RadiosityMesh mesh;                 // the solution; empty for a scene
  std::string valueSource;            // imported meshes: which data became B and how
  std::string gatherRefusal;          // why the final gather cannot run on this mesh; empty if it can
  std::vector<std::string> warnings;  // one line each, for the user
};

// Opens `path`: .gltf and .glb with radview's reader, .ply with its PLY reader, any other
// extension Assimp knows through Assimp. Throws Error(path, ...) when the file is missing, a
// directory, empty, of an unknown extension, malformed, or has nothing to show.
LoadedFile loadFile(const std::string& path, const ImportOptions& options = {});

}  // namespace radview
