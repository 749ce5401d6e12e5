#pragma once
// A file as the viewer and the commands show it: a solution file as it is, or a scene meshed
// uniformly and lit by its emitters (direct illumination, the first radiosity-like solution).
#include "mesh/load_file.h"
#include "mesh/radiosity_mesh.h"

#include <string>

namespace radview {

struct ViewedFile {
  LoadedFile file;           // its mesh moved into `mesh`
  RadiosityMesh mesh;        // what is drawn
  double elementSize = 0.0;  // for scenes: the uniform mesh's element size; 0 for solutions
  size_t tVertexCount = 0;
};

// elementSize <= 0 picks defaultElementSize(scene). Throws Error.
ViewedFile openForViewing(const std::string& path, double elementSize);

}  // namespace radview
