#pragma once
// The one entry point that opens whatever the user names: a glTF scene to solve, or a radview
// solution file (glTF with the RADVIEW_radiosity_mesh extension) to view.
#include "mesh/radiosity_mesh.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace radview {

struct LoadedFile {
  std::string path;
  bool isSolution = false;
  Scene scene;                        // the imported scene, quads merged; a solution's cameras only
  RadiosityMesh mesh;                 // the solution; empty for a scene
  std::vector<std::string> warnings;  // one line each, for the user
};

// Opens `path` (.gltf or .glb). Throws Error(path, ...) when the file is missing, a directory,
// empty, of an unknown extension, malformed, or has nothing to show.
LoadedFile loadFile(const std::string& path);

}  // namespace radview
