#include "interp/t_vertex_repair.h"

#include "interp/surface_triangulation.h"

#include <vector>

namespace radview {

RadiosityMesh repairTVertices(const RadiosityMesh& mesh, size_t* repaired) {
  const SurfaceTriangulation surface(mesh);
  std::vector<bool> hasTVertex(mesh.elements.size(), false);
  for (const TVertex& t : surface.topology().tVertices())
    if (mesh.elements[t.element].order() == ElementOrder::Linear) hasTVertex[t.element] = true;
  RadiosityMesh out = mesh;
  out.elements.clear();
  size_t count = 0;
  for (uint32_t e = 0; e < mesh.elements.size(); ++e) {
    if (!hasTVertex[e]) {
      out.elements.push_back(mesh.elements[e]);
      continue;
    }
    ++count;
    for (uint32_t t : surface.trianglesOf(e)) {
      const auto& n = surface.triangles()[t].node;
      out.elements.push_back(Element{{n[0], n[1], n[2]}, {}, mesh.elements[e].material, mesh.elements[e].surface});
    }
  }
  if (repaired) *repaired = count;
  return out;
}

}  // namespace radview
