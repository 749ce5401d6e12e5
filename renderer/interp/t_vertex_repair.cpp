#include "interp/t_vertex_repair.h"

#include "interp/surface_triangulation.h"

#include <algorithm>
#include <utility>
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
  // A tagged edge that a T-vertex splits becomes two tagged edges through it (the repaired
  // elements have the halves as edges, not the whole).
  const MeshTopology& topology = surface.topology();
  std::vector<DiscontinuityEdge> tags;
  for (const DiscontinuityEdge& d : mesh.discontinuities) {
    std::vector<std::pair<double, uint32_t>> inside;  // nodes on the open edge, by position along it
    const Vec3 a = mesh.nodes[d.a].position, b = mesh.nodes[d.b].position;
    for (const TVertex& t : topology.tVertices()) {
      const Element& e = mesh.elements[t.element];
      const uint32_t p = topology.positionId(e.corners[t.edge]),
                     q = topology.positionId(e.corners[(t.edge + 1) % e.corners.size()]);
      const uint32_t pa = topology.positionId(d.a), pb = topology.positionId(d.b);
      if ((p == pa && q == pb) || (p == pb && q == pa))
        inside.push_back({glm::dot(mesh.nodes[t.node].position - a, b - a), t.node});
    }
    std::sort(inside.begin(), inside.end());
    uint32_t from = d.a;
    for (const auto& [along, node] : inside) {
      tags.push_back({from, node, d.order});
      from = node;
    }
    tags.push_back({from, d.b, d.order});
  }
  out.discontinuities = tags;
  if (repaired) *repaired = count;
  return out;
}

}  // namespace radview
