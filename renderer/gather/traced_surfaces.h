#pragma once
// What the ray tracers (the final gather, eq. 9.9, and the path tracer) need of an opened file.
#include "scene/scene.h"
#include "solve/viewed_file.h"

#include <string>

namespace radview {

// The surfaces the path tracer traces: a scene's polygons as the file gives them, or the mesh's
// elements (trace/visible_elements.h's elementScene) for a solution or another tool's mesh.
Scene tracedSurfaces(const ViewedFile& viewed);

// Both integrate rho times the light around each point seen and add the emitters' E: a mesh
// imported without them (a PLY's colours alone) cannot be ray traced. The final gather also
// refuses a scene lit by its direct light alone: eq. 9.9 over it would show light the scene
// does not have. Throws Error(path, why), naming `method`.
void checkRayTracingRuns(const ViewedFile& viewed, const std::string& method);

}  // namespace radview
