#include "gather/traced_surfaces.h"

#include "core/error.h"
#include "trace/visible_elements.h"

namespace radview {

Scene tracedSurfaces(const ViewedFile& viewed) {
  return viewed.file.scene.polygons.empty() ? elementScene(viewed.mesh) : viewed.file.scene;
}

void checkRayTracingRuns(const ViewedFile& viewed, const std::string& method) {
  if (!viewed.file.gatherRefusal.empty())
    throw Error(viewed.file.path, method + " cannot run: " + viewed.file.gatherRefusal +
                                      "; the interpolants work on it (--method gouraud, clough-tocher, ...)");
  if (viewed.directLightOnly && method == "the final gather")
    throw Error(viewed.file.path,
                "the final gather cannot run with --direct-only: eq. 9.9 would gather from direct "
                "light alone, which the scene does not have (leave --direct-only out to solve the "
                "scene first, or use --method path-trace, which needs no solution)");
}

}  // namespace radview
