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

// elementSize <= 0 picks defaultElementSize(scene); `import` says how another tool's mesh is
// read (mesh/load_file.h). Throws Error.
ViewedFile openForViewing(const std::string& path, double elementSize, const ImportOptions& import = {});

// The final gather (eq. 9.9) integrates rho times the radiosity around each point seen and adds
// the emitters' E: a mesh imported without them (a PLY's colours alone) cannot be gathered.
// Throws Error(path, why) then.
void checkFinalGatherRuns(const ViewedFile& viewed);

}  // namespace radview
