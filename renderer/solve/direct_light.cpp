#include "solve/direct_light.h"

#include "core/parallel_for.h"
#include "geom/polygon.h"
#include "mesh/uniform_mesher.h"
#include "trace/form_factor.h"

#include <algorithm>

namespace radview {

namespace {

constexpr uint32_t kNoElement = UINT32_MAX;

struct Emitter {
  int polygon = -1;
  const std::vector<Vec3>* vertices = nullptr;
  Rgb E{0.0};
};

// The first element (in element order) that uses each node, corner or mid-edge.
std::vector<uint32_t> firstElementOfNodes(const RadiosityMesh& mesh) {
  std::vector<uint32_t> first(mesh.nodes.size(), kNoElement);
  for (uint32_t e = 0; e < mesh.elements.size(); ++e) {
    for (uint32_t node : mesh.elements[e].corners) first[node] = std::min(first[node], e);
    for (uint32_t node : mesh.elements[e].midEdge) first[node] = std::min(first[node], e);
  }
  return first;
}

}  // namespace

// C&W eq. 9.8 with B(x') = E(x') and V = 1: B = E + rho * sum_e E_e F(x -> e).
void solveDirectIllumination(const Scene& scene, RadiosityMesh& mesh) {
  std::vector<Emitter> emitters;
  for (int p : scene.emitters())
    emitters.push_back({p, &scene.polygons[p].vertices, scene.materials[scene.polygons[p].material].E});
  std::vector<Vec3> surfaceNormals;
  for (const Polygon& polygon : scene.polygons) surfaceNormals.push_back(unitNormal(polygon.vertices));
  const std::vector<uint32_t> firstElement = firstElementOfNodes(mesh);

  parallelFor(mesh.nodes.size(), [&](size_t i) {
    const uint32_t e = firstElement[i];
    if (e == kNoElement) return;
    const Element& element = mesh.elements[e];
    const Material& material = mesh.materials[element.material];
    const bool onSurface = element.surface >= 0 && element.surface < int(surfaceNormals.size());
    Vec3 n = onSurface ? surfaceNormals[element.surface] : Vec3(0.0);
    if (n == Vec3(0.0)) n = mesh.elementNormal(e);
    Node& node = mesh.nodes[i];
    Rgb B = material.E;
    if (n != Vec3(0.0))
      for (const Emitter& emitter : emitters)
        if (emitter.polygon != element.surface)  // an emitter does not light itself
          B += material.rho * emitter.E * pointToPolygonFormFactor(node.position, n, *emitter.vertices);
    node.B = B;
  });
}

RadiosityMesh meshAndLight(const Scene& scene, double elementSize) {
  RadiosityMesh mesh = meshUniformly(scene, elementSize);
  solveDirectIllumination(scene, mesh);
  return mesh;
}

double defaultElementSize(const Scene& scene) {
  const double diagonal = scene.bounds().diagonal();
  return diagonal > 0.0 && std::isfinite(diagonal) ? diagonal / 40.0 : 1.0;
}

}  // namespace radview
