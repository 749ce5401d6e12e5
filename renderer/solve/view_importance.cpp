#include "solve/view_importance.h"

#include "core/parallel_for.h"
#include "trace/camera_rays.h"
#include "trace/ray_caster.h"
#include "trace/visible_elements.h"

#include <sstream>

namespace radview {

namespace {

constexpr int32_t kNothing = -1, kBackFace = -2;

// What each pixel centre of the view sees: an element's front side (its index), the back of a
// surface (kBackFace), or nothing (kNothing).
std::vector<int32_t> frontElements(const RayCaster& caster, const SolveView& view) {
  const CameraRays rays(view.camera, view.width, view.height);
  std::vector<int32_t> seen(size_t(view.width) * size_t(view.height), kNothing);
  parallelFor(seen.size(), [&](size_t i) {
    const auto hit = caster.closestHit(rays.through(double(i % view.width) + 0.5, double(i / view.width) + 0.5));
    if (hit) seen[i] = hit->front ? int32_t(hit->polygon) : kBackFace;
  });
  return seen;
}

}  // namespace

std::vector<uint32_t> viewedPixels(const RadiosityMesh& mesh, const std::vector<SolveView>& views) {
  std::vector<uint32_t> pixels(mesh.elements.size(), 0);
  if (views.empty() || mesh.elements.empty()) return pixels;
  const RayCaster caster(elementScene(mesh));
  for (const SolveView& view : views)
    for (int32_t e : frontElements(caster, view))
      if (e >= 0) ++pixels[size_t(e)];
  return pixels;
}

UsableViews usableViews(const RadiosityMesh& mesh, const std::vector<SolveView>& views) {
  UsableViews usable;
  if (views.empty()) return usable;
  const RayCaster caster(elementScene(mesh));
  for (const SolveView& view : views) {
    size_t front = 0, back = 0;
    for (int32_t e : frontElements(caster, view)) {
      front += e >= 0;
      back += e == kBackFace;
    }
    if (front > 0) {
      usable.views.push_back(view);
      continue;
    }
    std::ostringstream line;
    const Vec3& eye = view.camera.eye;
    line << "view '" << view.name << "' (eye " << eye.x << "," << eye.y << "," << eye.z << ") ";
    if (back > 0)
      line << "sees only the backs of surfaces (" << back << " of its " << size_t(view.width) * view.height
           << " pixels): its eye is inside a solid or behind a wall";
    else
      line << "sees nothing of the scene";
    line << "; it is left out";
    usable.warnings.push_back(line.str());
  }
  return usable;
}

}  // namespace radview
