#include "mesh/display_mesh.h"

#include "geom/polygon.h"
#include "mesh/topology.h"

#include <algorithm>
#include <set>
#include <utility>

namespace radview {

namespace {

glm::vec3 toFloat(const Vec3& v) { return glm::vec3(v); }

}  // namespace

std::vector<std::array<uint32_t, 3>> elementTriangles(const RadiosityMesh& mesh, size_t element,
                                                      size_t firstCorner) {
  const Element& e = mesh.elements[element];
  const size_t n = e.corners.size();
  if (e.order() == ElementOrder::Quadratic && n == 3) {
    const auto& c = e.corners;
    const auto& m = e.midEdge;  // m[i] on edge c[i] -> c[i+1]
    return {{c[0], m[0], m[2]}, {m[0], c[1], m[1]}, {m[2], m[1], c[2]}, {m[0], m[1], m[2]}};
  }
  std::vector<uint32_t> corners(n);
  std::vector<Vec3> polygon(n);
  for (size_t i = 0; i < n; ++i) {
    corners[i] = e.corners[(i + firstCorner) % n];
    polygon[i] = mesh.nodes[corners[i]].position;
  }
  std::vector<std::array<uint32_t, 3>> out;
  for (const auto& t : triangulatePolygon(polygon)) out.push_back({corners[t[0]], corners[t[1]], corners[t[2]]});
  return out;
}

DisplayMesh buildDisplayMesh(const RadiosityMesh& mesh) {
  DisplayMesh out;
  std::set<std::pair<uint32_t, uint32_t>> drawnEdges;
  auto addEdge = [&](uint32_t a, uint32_t b) {
    if (drawnEdges.insert({std::min(a, b), std::max(a, b)}).second) {
      out.elementEdges.push_back(toFloat(mesh.nodes[a].position));
      out.elementEdges.push_back(toFloat(mesh.nodes[b].position));
    }
  };

  for (size_t e = 0; e < mesh.elements.size(); ++e) {
    const Element& element = mesh.elements[e];
    const Rgb Bflat = mesh.meanB(e);
    for (const auto& t : elementTriangles(mesh, e))
      for (uint32_t node : t)
        out.triangles.push_back(
            {toFloat(mesh.nodes[node].position), toFloat(mesh.nodes[node].B), toFloat(Bflat), uint32_t(e)});
    const auto& c = element.corners;
    const size_t n = c.size();
    for (size_t i = 0; i < n; ++i) {
      if (element.order() == ElementOrder::Quadratic) {
        addEdge(c[i], element.midEdge[i]);
        addEdge(element.midEdge[i], c[(i + 1) % n]);
      } else {
        addEdge(c[i], c[(i + 1) % n]);
      }
    }
  }
  for (const DiscontinuityEdge& d : mesh.discontinuities) {
    if (d.order == Continuity::C1) continue;
    const glm::vec4 color = d.order == Continuity::Cm1 ? kDiscontinuityCm1Color : kDiscontinuityC0Color;
    out.discontinuityEdges.push_back({toFloat(mesh.nodes[d.a].position), color});
    out.discontinuityEdges.push_back({toFloat(mesh.nodes[d.b].position), color});
  }
  const MeshTopology topology(mesh);
  for (const TVertex& t : topology.tVertices())
    out.tVertices.push_back({toFloat(mesh.nodes[t.node].position), kTVertexColor});
  return out;
}

}  // namespace radview
