#include "trace/visible_elements.h"

#include "core/parallel_for.h"
#include "trace/camera_rays.h"
#include "trace/ray_caster.h"

namespace radview {

Scene elementScene(const RadiosityMesh& mesh) {
  Scene scene;
  scene.materials = mesh.materials;
  scene.polygons.reserve(mesh.elements.size());
  for (size_t e = 0; e < mesh.elements.size(); ++e)
    scene.polygons.push_back({mesh.cornerPositions(e), mesh.elements[e].material});
  return scene;
}

std::vector<int32_t> visibleElements(const RadiosityMesh& mesh, const Camera& camera, int width, int height) {
  const RayCaster caster(elementScene(mesh));
  const CameraRays rays(camera, width, height);
  std::vector<int32_t> element(size_t(width) * height, -1);
  parallelFor(element.size(), [&](size_t i) {
    const auto hit = caster.closestHit(rays.through(double(i % width) + 0.5, double(i / width) + 0.5));
    if (hit) element[i] = int32_t(hit->polygon);
  });
  return element;
}

}  // namespace radview
