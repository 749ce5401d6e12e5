#include "mesh/display_mesh.h"

#include "core/parallel_for.h"
#include "geom/polygon.h"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace radview {

namespace {

glm::vec3 toFloat(const Vec3& v) { return glm::vec3(v); }

}  // namespace

std::vector<std::vector<TVertex>> tVerticesByElement(const RadiosityMesh& mesh, const MeshTopology& topology) {
  std::vector<std::vector<TVertex>> out(mesh.elements.size());
  for (const TVertex& t : topology.tVertices()) out[t.element].push_back(t);
  return out;
}

std::vector<std::array<uint32_t, 3>> elementTriangles(const RadiosityMesh& mesh, size_t element, size_t firstCorner) {
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

std::vector<std::array<DrawnCorner, 3>> watertightTriangles(const RadiosityMesh& mesh, size_t element,
                                                            const std::vector<TVertex>& tVertices,
                                                            Rgb Node::*value) {
  std::vector<std::array<DrawnCorner, 3>> triangles;
  for (const auto& t : elementTriangles(mesh, element))
    triangles.push_back({DrawnCorner{t[0], mesh.nodes[t[0]].*value}, DrawnCorner{t[1], mesh.nodes[t[1]].*value},
                         DrawnCorner{t[2], mesh.nodes[t[2]].*value}});
  const Element& e = mesh.elements[element];
  const size_t n = e.corners.size();
  for (size_t k = 0; k < n; ++k) {
    // The T-vertices on edge k, by their position along it.
    std::vector<const TVertex*> along;
    for (const TVertex& t : tVertices)
      if (t.element == element && t.edge == k) along.push_back(&t);
    if (along.empty()) continue;
    std::sort(along.begin(), along.end(), [](const TVertex* a, const TVertex* b) { return a->t < b->t; });
    // Nodes sharing a position (the two sides of a C-1 edge) are one point of the outline.
    along.erase(
        std::unique(along.begin(), along.end(), [](const TVertex* a, const TVertex* b) { return a->t == b->t; }),
        along.end());
    const Vec3 A = mesh.nodes[e.corners[k]].position, AB = mesh.nodes[e.corners[(k + 1) % n]].position - A;
    auto onEdge = [&](uint32_t node) {
      return node == e.corners[k] || node == e.corners[(k + 1) % n] ||
             (e.order() == ElementOrder::Quadratic && node == e.midEdge[k]);
    };
    auto tOf = [&](uint32_t node) { return glm::dot(mesh.nodes[node].position - A, AB) / glm::dot(AB, AB); };
    // The triangles with a side on edge k (a linear element has one, a quadratic triangle two
    // halves): each is fanned from its third corner through the T-vertices strictly inside it.
    const size_t count = triangles.size();
    for (size_t i = 0; i < count; ++i)
      for (int s = 0; s < 3; ++s) {
        const DrawnCorner u = triangles[i][s], v = triangles[i][(s + 1) % 3], w = triangles[i][(s + 2) % 3];
        if (!onEdge(u.node) || !onEdge(v.node)) continue;
        const double tu = tOf(u.node), tv = tOf(v.node);
        std::vector<DrawnCorner> path{u};
        auto add = [&](const TVertex* t) {
          if (std::min(tu, tv) < t->t && t->t < std::max(tu, tv))
            path.push_back({t->node, u.B + (v.B - u.B) * ((t->t - tu) / (tv - tu))});
        };
        if (tu < tv)
          std::for_each(along.begin(), along.end(), add);
        else
          std::for_each(along.rbegin(), along.rend(), add);
        if (path.size() == 1) continue;
        path.push_back(v);
        triangles[i] = {path[0], path[1], w};
        for (size_t p = 1; p + 1 < path.size(); ++p) triangles.push_back({path[p], path[p + 1], w});
        break;
      }
  }
  return triangles;
}

std::vector<DisplayVertex> displayTriangles(const RadiosityMesh& mesh, const MeshTopology& topology,
                                            Rgb Node::*value) {
  const std::vector<std::vector<TVertex>> tVertices = tVerticesByElement(mesh, topology);
  // Elements in blocks, each block's triangles its own list, the blocks on every core; the
  // lists then joined in element order, each freed once copied.
  constexpr size_t kBlock = 4096;
  std::vector<std::vector<DisplayVertex>> blocks((mesh.elements.size() + kBlock - 1) / kBlock);
  parallelFor(
      blocks.size(),
      [&](size_t block) {
        std::vector<DisplayVertex>& triangles = blocks[block];
        for (size_t e = block * kBlock; e < std::min(mesh.elements.size(), (block + 1) * kBlock); ++e) {
          const Element& element = mesh.elements[e];
          Rgb flat(0.0);  // the mean of the element's nodal values, as RadiosityMesh::meanB
          for (const auto* list : {&element.corners, &element.midEdge})
            for (uint32_t node : *list) flat += mesh.nodes[node].*value;
          flat /= double(element.corners.size() + element.midEdge.size());
          for (const auto& t : watertightTriangles(mesh, e, tVertices[e], value))
            for (const DrawnCorner& c : t)
              triangles.push_back({toFloat(mesh.nodes[c.node].position), toFloat(c.B), toFloat(flat), uint32_t(e)});
        }
      },
      1);
  size_t total = 0;
  for (const auto& block : blocks) total += block.size();
  std::vector<DisplayVertex> triangles;
  triangles.reserve(total);
  for (auto& block : blocks) {
    triangles.insert(triangles.end(), block.begin(), block.end());
    block = {};
  }
  return triangles;
}

namespace {

// Element edges by their end positions (MeshTopology's ids), each drawn once, in the direction
// its first element runs it (a line's pixels depend on its direction).
std::vector<glm::vec3> elementEdgeLines(const RadiosityMesh& mesh, const MeshTopology& topology) {
  struct DrawnEdge {
    uint64_t positions;
    uint32_t from, to;
  };
  std::vector<DrawnEdge> drawnEdges;
  auto addEdge = [&](uint32_t a, uint32_t b) {
    const uint32_t p = topology.positionId(a), q = topology.positionId(b);
    drawnEdges.push_back({uint64_t(std::min(p, q)) << 32 | std::max(p, q), a, b});
  };
  for (const Element& element : mesh.elements) {
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
  std::stable_sort(drawnEdges.begin(), drawnEdges.end(),
                   [](const DrawnEdge& x, const DrawnEdge& y) { return x.positions < y.positions; });
  drawnEdges.erase(std::unique(drawnEdges.begin(), drawnEdges.end(),
                               [](const DrawnEdge& x, const DrawnEdge& y) { return x.positions == y.positions; }),
                   drawnEdges.end());
  std::vector<glm::vec3> lines;
  lines.reserve(2 * drawnEdges.size());
  for (const DrawnEdge& edge : drawnEdges) {
    lines.push_back(toFloat(mesh.nodes[edge.from].position));
    lines.push_back(toFloat(mesh.nodes[edge.to].position));
  }
  return lines;
}

}  // namespace

DisplayMesh buildDisplayMesh(const RadiosityMesh& mesh, const MeshTopology& topology, bool elementEdges) {
  DisplayMesh out;
  if (elementEdges) out.elementEdges = elementEdgeLines(mesh, topology);
  for (const DiscontinuityEdge& d : mesh.discontinuities) {
    if (d.order == Continuity::C1) continue;
    const glm::vec4 colour = d.order == Continuity::Cm1 ? kDiscontinuityCm1Colour : kDiscontinuityC0Colour;
    out.discontinuityEdges.push_back({toFloat(mesh.nodes[d.a].position), colour});
    out.discontinuityEdges.push_back({toFloat(mesh.nodes[d.b].position), colour});
  }
  for (const TVertex& t : topology.tVertices())
    out.tVertices.push_back({toFloat(mesh.nodes[t.node].position), kTVertexColour});
  return out;
}

}  // namespace radview
