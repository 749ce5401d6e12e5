#include "mesh/display_mesh.h"

#include "geom/polygon.h"

#include <algorithm>
#include <set>
#include <utility>

namespace radview {

namespace {

glm::vec3 f(const Vec3& v) { return glm::vec3(v); }

void addTriangle(DisplayMesh& out, const RadiosityMesh& mesh, const Rgb& Bflat, uint32_t a, uint32_t b, uint32_t c) {
  for (uint32_t n : {a, b, c}) out.triangles.push_back({f(mesh.nodes[n].position), f(mesh.nodes[n].B), f(Bflat)});
}

}  // namespace

DisplayMesh buildDisplayMesh(const RadiosityMesh& mesh) {
  DisplayMesh out;
  std::set<std::pair<uint32_t, uint32_t>> drawnEdges;
  auto addEdge = [&](uint32_t a, uint32_t b) {
    if (drawnEdges.insert({std::min(a, b), std::max(a, b)}).second) {
      out.elementEdges.push_back(f(mesh.nodes[a].position));
      out.elementEdges.push_back(f(mesh.nodes[b].position));
    }
  };

  for (size_t e = 0; e < mesh.elements.size(); ++e) {
    const Element& element = mesh.elements[e];
    const Rgb Bflat = mesh.meanB(e);
    const auto& c = element.corners;
    const size_t n = c.size();
    if (element.order() == ElementOrder::Quadratic && n == 3) {
      const auto& m = element.midEdge;  // m[i] on edge c[i] -> c[i+1]
      addTriangle(out, mesh, Bflat, c[0], m[0], m[2]);
      addTriangle(out, mesh, Bflat, m[0], c[1], m[1]);
      addTriangle(out, mesh, Bflat, m[2], m[1], c[2]);
      addTriangle(out, mesh, Bflat, m[0], m[1], m[2]);
    } else {
      for (const auto& t : triangulatePolygon(mesh.cornerPositions(e))) addTriangle(out, mesh, Bflat, c[t[0]], c[t[1]], c[t[2]]);
    }
    for (size_t i = 0; i < n; ++i) {
      if (element.order() == ElementOrder::Quadratic) {
        addEdge(c[i], element.midEdge[i]);
        addEdge(element.midEdge[i], c[(i + 1) % n]);
      } else {
        addEdge(c[i], c[(i + 1) % n]);
      }
    }
  }
  return out;
}

}  // namespace radview
