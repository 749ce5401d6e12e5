#pragma once
// Derived structure of a radiosity mesh: which nodes share a position, which elements share
// an edge, where T-vertices are, and the continuity of every edge.
#include "mesh/radiosity_mesh.h"

#include <cstdint>
#include <vector>

namespace radview {

struct EdgeSide {
  uint32_t element = 0;
  uint32_t edge = 0;  // edge i runs corners[i] -> corners[i+1]
};

struct MeshEdge {
  uint32_t a = 0, b = 0;  // position ids (see MeshTopology::positionId), a < b
  uint32_t firstSide = 0,
           sideCount = 0;  // its sides (MeshTopology::sides); 1: boundary, 2: interior, more: non-manifold
  Continuity continuity = Continuity::C1;  // tagged order, C1 where untagged
};

// The sides of one edge, in element order: a view into MeshTopology's one array of sides.
struct EdgeSides {
  const EdgeSide* first = nullptr;
  uint32_t count = 0;
  const EdgeSide* begin() const { return first; }
  const EdgeSide* end() const { return first + count; }
  size_t size() const { return count; }
  const EdgeSide& operator[](size_t i) const { return first[i]; }
};

// A T-vertex (C&W §9.2): a node lying strictly inside an edge of a coplanar element that
// does not have the node, as adaptive subdivision leaves where one element is split and its
// neighbour is not.
struct TVertex {
  uint32_t node = 0;
  uint32_t element = 0;  // the element whose edge the node lies on
  uint32_t edge = 0;
  double t = 0.0;  // position along the edge, in (0, 1)
};

// Throws Error, as MeshTopology does, for a discontinuity edge that is not an element edge:
// what a reader checks of the tags without the whole topology. Cheap where every tag names
// two consecutive corners of an element (as radview writes them); a tag that does not is
// looked up by position through MeshTopology.
void checkDiscontinuityEdges(const RadiosityMesh& mesh);

class MeshTopology {
 public:
  // Nodes closer than weldTolerance * (bounding-box diagonal) share a position id; edges are
  // matched through position ids, so elements across a C-1 edge (duplicated nodes) are
  // still neighbours. The mesh must pass validateMesh. Throws Error for a discontinuity edge
  // that is not an element edge. About linear in the mesh size (hash grids and one sort, no
  // pairs, a few arrays rather than a list per edge or element), the T-vertex search on every
  // core.
  explicit MeshTopology(const RadiosityMesh& mesh, double weldTolerance = 1e-7);

  uint32_t positionId(uint32_t node) const { return positionId_[node]; }
  uint32_t positionCount() const { return positionCount_; }
  // The edges, ordered by their position ids (a, then b).
  const std::vector<MeshEdge>& edges() const { return edges_; }
  EdgeSides sides(const MeshEdge& edge) const { return {sides_.data() + edge.firstSide, edge.sideCount}; }
  // Index into edges() of edge `edge` of element `element`.
  uint32_t edgeIndex(uint32_t element, uint32_t edge) const { return elementEdges_[elementFirstEdge_[element] + edge]; }
  // The element across that edge, or -1 on a boundary (or a non-manifold edge).
  int64_t neighbour(uint32_t element, uint32_t edge) const;
  const std::vector<TVertex>& tVertices() const { return tVertices_; }
  // The number of edges whose continuity is `order` (C1 counts the untagged ones).
  size_t countEdges(Continuity order) const;
  // Edge `edge` retagged, the mesh's nodes unchanged: what the topology of the retagged mesh
  // would be (edit/continuity_edit.h keeps its topology so).
  void setContinuity(uint32_t edge, Continuity order) { edges_[edge].continuity = order; }

 private:
  void findTVertices(const RadiosityMesh& mesh, const std::vector<Vec3>& positions, double weldDistance);

  std::vector<uint32_t> positionId_;
  uint32_t positionCount_ = 0;
  std::vector<MeshEdge> edges_;
  std::vector<EdgeSide> sides_;             // grouped by edge, in edges_' order
  std::vector<uint32_t> elementFirstEdge_;  // per element: where its edges start in elementEdges_
  std::vector<uint32_t> elementEdges_;      // per element, per edge: index in edges_
  std::vector<TVertex> tVertices_;
};

}  // namespace radview
