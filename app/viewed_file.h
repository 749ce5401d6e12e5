#pragma once
// A file as the viewer and the commands show it: a solution file as it is, or a scene solved as
// `radview solve` solves it (app/scene_light.h), or with --direct-only meshed uniformly and lit
// by its emitters' unoccluded direct light (a preview).
#include "app/scene_light.h"
#include "mesh/load_file.h"
#include "mesh/radiosity_mesh.h"

#include <functional>
#include <string>

namespace radview {

struct ViewedFile {
  LoadedFile file;           // its mesh moved into `mesh`
  RadiosityMesh mesh;        // what is drawn
  double elementSize = 0.0;  // for scenes: the uniform mesh's element size, or the solve's patches'; 0 for solutions
  size_t tVertexCount = 0;
  std::string lighting;  // for scenes: how they were lit, in words (a solve's summary, or kDirectOnlyLabel)
  bool directLightOnly = false;  // a scene lit by --direct-only: it has no solution to gather from
};

// elementSize <= 0 picks the default (defaultElementSize(scene), or the solve's patch size);
// `import` says how another tool's mesh is read (mesh/load_file.h); `light` how a scene is lit.
// `checkLoaded`, if given, sees the file once it is read and before a scene is meshed or solved:
// options that depend on the file (a camera) are refused there, not after a solve. A solve shows
// its progress on standard error when that is a terminal. Throws Error.
ViewedFile openForViewing(const std::string& path, double elementSize, const ImportOptions& import,
                          const SceneLightOptions& light,
                          const std::function<void(const LoadedFile&)>& checkLoaded = nullptr);

// The final gather (eq. 9.9) and the path tracer integrate rho times the light around each point
// seen and add the emitters' E: a mesh imported without them (a PLY's colours alone) cannot be
// ray traced. Throws Error(path, why) then, naming `method`.
// The surfaces the path tracer traces: a scene's polygons as the file gives them, or the mesh's
// elements (gather/visible_elements.h's elementScene) for a solution or another tool's mesh.
Scene tracedSurfaces(const ViewedFile& viewed);

// The final gather also refuses a scene lit by its direct light alone: eq. 9.9 over it would
// show light the scene does not have.
void checkRayTracingRuns(const ViewedFile& viewed, const std::string& method);

}  // namespace radview
