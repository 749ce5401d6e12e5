#include "mesh/topology.h"

#include "core/error.h"
#include "core/parallel_for.h"
#include "geom/point_grid.h"
#include "geom/weld.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>

namespace radview {

namespace {

// Compressed lists: the items of group g are items[start[g] .. start[g+1]).
struct Lists {
  std::vector<uint32_t> start, items;
  template <typename F>
  void forEach(uint32_t group, F f) const {
    for (uint32_t k = start[group]; k < start[group + 1]; ++k) f(items[k]);
  }
};

// Groups the values 0 .. groupOf.size()-1 by groupOf[value].
Lists groupBy(const std::vector<uint32_t>& groupOf, uint32_t groupCount) {
  Lists lists;
  lists.start.assign(groupCount + 1, 0);
  for (uint32_t g : groupOf) ++lists.start[g + 1];
  for (uint32_t g = 0; g < groupCount; ++g) lists.start[g + 1] += lists.start[g];
  lists.items.resize(groupOf.size());
  std::vector<uint32_t> fill(lists.start.begin(), lists.start.end() - 1);
  for (uint32_t v = 0; v < groupOf.size(); ++v) lists.items[fill[groupOf[v]]++] = v;
  return lists;
}

// The elements each node belongs to (as a corner or a mid-edge node).
Lists elementsOfNodes(const RadiosityMesh& mesh) {
  std::vector<uint32_t> nodeOfUse, elementOfUse;
  for (uint32_t e = 0; e < mesh.elements.size(); ++e)
    for (const auto* list : {&mesh.elements[e].corners, &mesh.elements[e].midEdge})
      for (uint32_t node : *list) {
        nodeOfUse.push_back(node);
        elementOfUse.push_back(e);
      }
  Lists lists = groupBy(nodeOfUse, uint32_t(mesh.nodes.size()));
  for (uint32_t& use : lists.items) use = elementOfUse[use];
  return lists;
}

}  // namespace

MeshTopology::MeshTopology(const RadiosityMesh& mesh, double weldTolerance) {
  std::vector<Vec3> nodePositions;
  nodePositions.reserve(mesh.nodes.size());
  for (const Node& node : mesh.nodes) nodePositions.push_back(node.position);
  const double weldDistance = weldTolerance * mesh.bounds().diagonal();
  const WeldedPoints welded = weldPoints(nodePositions, weldDistance);
  positionId_ = welded.id;
  positionCount_ = welded.count();

  // Edges by their end positions: across a C-1 edge the two sides have their own nodes but
  // the same positions, so they still meet here. Every element edge is a use (a, b); the uses
  // are ordered by a, then b, by counting (stable, so each edge's sides stay in element
  // order), and each run of equal (a, b) is one edge.
  struct Use {
    uint32_t a, b, element, edge;
  };
  std::vector<Use> uses;
  elementFirstEdge_.reserve(mesh.elements.size() + 1);
  for (uint32_t e = 0; e < mesh.elements.size(); ++e) {
    const std::vector<uint32_t>& corners = mesh.elements[e].corners;
    elementFirstEdge_.push_back(uint32_t(uses.size()));
    for (uint32_t i = 0; i < corners.size(); ++i) {
      RADVIEW_CHECK(corners[i] < mesh.nodes.size());
      const uint32_t a = positionId_[corners[i]], b = positionId_[corners[(i + 1) % corners.size()]];
      uses.push_back({std::min(a, b), std::max(a, b), e, i});
    }
  }
  elementFirstEdge_.push_back(uint32_t(uses.size()));
  std::vector<uint32_t> aOfUse(uses.size());
  for (size_t u = 0; u < uses.size(); ++u) aOfUse[u] = uses[u].a;
  const Lists usesByA = groupBy(aOfUse, positionCount_);
  aOfUse = {};
  elementEdges_.resize(uses.size());
  sides_.reserve(uses.size());
  edges_.reserve(uses.size() / 2 + 1);  // each interior edge has two uses
  std::vector<uint32_t> run;
  for (uint32_t a = 0; a < positionCount_; ++a) {
    run.assign(usesByA.items.begin() + usesByA.start[a], usesByA.items.begin() + usesByA.start[a + 1]);
    std::stable_sort(run.begin(), run.end(), [&](uint32_t x, uint32_t y) { return uses[x].b < uses[y].b; });
    for (size_t k = 0; k < run.size(); ++k) {
      const Use& use = uses[run[k]];
      if (k == 0 || uses[run[k - 1]].b != use.b) {
        MeshEdge edge;
        edge.a = use.a;
        edge.b = use.b;
        edge.firstSide = uint32_t(sides_.size());
        edges_.push_back(edge);
      }
      ++edges_.back().sideCount;
      sides_.push_back({use.element, use.edge});
      elementEdges_[elementFirstEdge_[use.element] + use.edge] = uint32_t(edges_.size() - 1);
    }
  }

  // An edge tagged more than once keeps its lowest order (the weaker continuity wins).
  for (size_t d = 0; d < mesh.discontinuities.size(); ++d) {
    const DiscontinuityEdge& tag = mesh.discontinuities[d];
    const std::string name = "discontinuity edge " + std::to_string(d) + " (nodes " + std::to_string(tag.a) + "-" +
                             std::to_string(tag.b) + ")";
    if (tag.a >= mesh.nodes.size() || tag.b >= mesh.nodes.size()) throw Error(name + " refers to a node out of range");
    const uint32_t a = std::min(positionId_[tag.a], positionId_[tag.b]),
                   b = std::max(positionId_[tag.a], positionId_[tag.b]);
    auto it = std::lower_bound(
        edges_.begin(), edges_.end(), std::make_pair(a, b),
        [](const MeshEdge& e, const std::pair<uint32_t, uint32_t>& key) { return std::make_pair(e.a, e.b) < key; });
    if (it == edges_.end() || it->a != a || it->b != b) throw Error(name + " is not an element edge");
    it->continuity = std::min(it->continuity, tag.order);
  }

  findTVertices(mesh, welded.position, weldDistance);
}

// C&W §9.2: a T-vertex is a node inside an edge of a coplanar element that does not have it.
// Coplanar means parallel normals facing the same way (the two faces of a thin wall are not one
// surface); the planes then coincide, since both contain the node. Walls meeting at a corner
// are not coplanar, so a floor node on the bottom edge of a wall is no T-vertex.
void MeshTopology::findTVertices(const RadiosityMesh& mesh, const std::vector<Vec3>& positions, double weldDistance) {
  std::vector<Vec3> normals;
  normals.reserve(mesh.elements.size());
  for (size_t e = 0; e < mesh.elements.size(); ++e) normals.push_back(mesh.elementNormal(e));
  const Lists elementsOfNode = elementsOfNodes(mesh);
  const Lists nodesAtPosition = groupBy(positionId_, positionCount_);
  auto hasPosition = [&](uint32_t element, uint32_t position) {
    const Element& el = mesh.elements[element];
    for (const auto* list : {&el.corners, &el.midEdge})
      for (uint32_t node : *list)
        if (positionId_[node] == position) return true;
    return false;
  };
  auto coplanarWithNode = [&](uint32_t element, uint32_t node) {
    bool coplanar = false;
    elementsOfNode.forEach(node, [&](uint32_t own) {
      coplanar |= normals[element] != Vec3(0.0) && glm::dot(normals[own], normals[element]) >= 1.0 - 1e-6;
    });
    return coplanar;
  };

  // Grid cells about the mean edge length: an edge then meets a few cells per unit of length.
  double lengthSum = 0.0;
  for (const MeshEdge& edge : edges_) lengthSum += glm::distance(positions[edge.a], positions[edge.b]);
  if (!(lengthSum > 0.0)) return;
  const double diagonal = mesh.bounds().diagonal();
  const double cellSize = std::max(lengthSum / double(edges_.size()), 1e-6 * diagonal);
  // Cells start off the mesh's lattice: a mesh of axis-aligned elements about a cell across
  // then has its nodes inside cells, not on their faces, so that an edge's box meets 2 cells
  // rather than 12. Any origin finds the same points.
  PointGrid grid(mesh.bounds().lo - Vec3(0.377 * cellSize), cellSize, positions.size());
  for (uint32_t p = 0; p < positions.size(); ++p) grid.insert(p, positions[p]);

  // Edges in blocks, each block's T-vertices its own list: the blocks run on every core.
  constexpr size_t kBlock = 4096;
  std::vector<std::vector<TVertex>> found((edges_.size() + kBlock - 1) / kBlock);
  parallelFor(
      found.size(),
      [&](size_t block) {
        std::vector<uint32_t> near;
        for (size_t index = block * kBlock; index < std::min(edges_.size(), (block + 1) * kBlock); ++index) {
          const MeshEdge& edge = edges_[index];
          const Vec3 A = positions[edge.a], B = positions[edge.b];
          const double L = glm::distance(A, B);
          if (L == 0.0) continue;
          // "On the edge": within a relative 1e-5 of its length (or the weld distance) of its line.
          const double tolerance = 1e-5 * L + weldDistance;
          // The edge in pieces no longer than a cell; the boxes about them, grown by twice the
          // tolerance, hold every point within `tolerance` of the edge, and each meets a few cells.
          const int steps = int(std::ceil(L / cellSize));  // cellSize >= 1e-6 diagonal: at most 1e6
          near.clear();
          for (int k = 0; k < steps; ++k) {
            const Vec3 p0 = A + (double(k) / steps) * (B - A), p1 = A + (double(k + 1) / steps) * (B - A);
            grid.forEachNear(glm::min(p0, p1) - Vec3(2.0 * tolerance), glm::max(p0, p1) + Vec3(2.0 * tolerance),
                             [&](uint32_t p) { near.push_back(p); });
          }
          std::sort(near.begin(), near.end());
          near.erase(std::unique(near.begin(), near.end()), near.end());
          for (uint32_t p : near) {
            if (p == edge.a || p == edge.b) continue;
            const double t = glm::dot(positions[p] - A, B - A) / (L * L);
            if (t * L <= tolerance || (1.0 - t) * L <= tolerance) continue;
            if (glm::distance(positions[p], A + t * (B - A)) > tolerance) continue;
            nodesAtPosition.forEach(p, [&](uint32_t node) {
              for (const EdgeSide& side : sides(edge)) {
                if (hasPosition(side.element, p) || !coplanarWithNode(side.element, node)) continue;
                // t runs from edge.a; the side's edge may run the other way.
                const bool forward = positionId_[mesh.elements[side.element].corners[side.edge]] == edge.a;
                found[block].push_back({node, side.element, side.edge, forward ? t : 1.0 - t});
              }
            });
          }
        }
      },
      1);
  for (const std::vector<TVertex>& list : found) tVertices_.insert(tVertices_.end(), list.begin(), list.end());
  std::sort(tVertices_.begin(), tVertices_.end(), [](const TVertex& x, const TVertex& y) {
    return std::tie(x.element, x.edge, x.t, x.node) < std::tie(y.element, y.edge, y.t, y.node);
  });
}

void checkDiscontinuityEdges(const RadiosityMesh& mesh) {
  if (mesh.discontinuities.empty()) return;
  auto key = [](uint32_t a, uint32_t b) { return uint64_t(std::min(a, b)) << 32 | std::max(a, b); };
  std::vector<bool> tagged(mesh.nodes.size(), false);
  for (const DiscontinuityEdge& tag : mesh.discontinuities) {
    if (tag.a >= mesh.nodes.size() || tag.b >= mesh.nodes.size()) {
      const MeshTopology named(mesh);  // throws, naming the tag
      return;
    }
    tagged[tag.a] = tagged[tag.b] = true;
  }
  std::vector<uint64_t> edges;  // the element edges between tagged nodes
  for (const Element& element : mesh.elements)
    for (size_t i = 0; i < element.corners.size(); ++i) {
      const uint32_t a = element.corners[i], b = element.corners[(i + 1) % element.corners.size()];
      if (a < tagged.size() && b < tagged.size() && tagged[a] && tagged[b]) edges.push_back(key(a, b));
    }
  std::sort(edges.begin(), edges.end());
  for (const DiscontinuityEdge& tag : mesh.discontinuities)
    if (!std::binary_search(edges.begin(), edges.end(), key(tag.a, tag.b))) {
      const MeshTopology byPosition(mesh);  // across duplicated nodes; throws for an edge that is none
      return;
    }
}

int64_t MeshTopology::neighbour(uint32_t element, uint32_t edge) const {
  const EdgeSides sides = this->sides(edges_[edgeIndex(element, edge)]);
  if (sides.size() != 2) return -1;
  const bool first = sides[0].element == element && sides[0].edge == edge;
  return sides[first ? 1 : 0].element;
}

size_t MeshTopology::countEdges(Continuity order) const {
  return size_t(std::count_if(edges_.begin(), edges_.end(), [&](const MeshEdge& e) { return e.continuity == order; }));
}

}  // namespace radview
