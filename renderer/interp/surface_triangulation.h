#pragma once
// The triangle mesh on which the C1 interpolants are built (C&W §9.2.2 constructs them on
// triangles): every element cut into triangles, with each triangle's neighbours across its
// edges and the continuity B must have there.
//
// How elements are cut, so that the result does not depend on the view or on how the file
// numbers the corners:
//  - nodes of neighbours that lie on an element's edge (T-vertices, C&W §9.2) are first
//    inserted into that element's boundary, so the triangles meet edge to edge (Baum et al.);
//  - the polygon is then triangulated without new vertices by a constrained Delaunay
//    triangulation (for a convex quad: the diagonal that maximises the smallest angle),
//    started from the corner with the smallest (x, y, z), so ties (a square) are broken by
//    position, not numbering; near ties are rounded to exact ones, so neither is the scale
//    or the distance from the origin.
// Quadratic elements are cut over their corners only, without T-vertex insertion.
#include "core/types.h"
#include "mesh/radiosity_mesh.h"
#include "mesh/topology.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace radview {

struct SurfaceTriangle {
  std::array<uint32_t, 3> node{};  // counter-clockwise about the element's normal
  uint32_t element = 0;
  // Edge k runs node[k] -> node[k+1]. The triangle across it, in the same plane, or -1 (a
  // boundary, or a crease between two planes: B need not be smooth across either).
  std::array<int32_t, 3> neighbour{-1, -1, -1};
  // Across edge k: C1 inside an element and across untagged edges; the tagged order on a
  // discontinuity edge; C-1 where the two sides have different nodes (their values may
  // differ). Meaningless where neighbour is -1.
  std::array<Continuity, 3> continuity{Continuity::C1, Continuity::C1, Continuity::C1};
};

class SurfaceTriangulation {
 public:
  explicit SurfaceTriangulation(const RadiosityMesh& mesh);
  // On the mesh's own topology (MeshTopology(mesh)), built once and shared.
  SurfaceTriangulation(const RadiosityMesh& mesh, std::shared_ptr<const MeshTopology> topology);

  const RadiosityMesh& mesh() const { return mesh_; }
  const MeshTopology& topology() const { return *topology_; }
  const std::vector<SurfaceTriangle>& triangles() const { return triangles_; }
  // The triangles of `element`: consecutive indices, in the order they were cut.
  struct TriangleRange {
    struct Index {
      uint32_t i;
      uint32_t operator*() const { return i; }
      Index& operator++() { return ++i, *this; }
      bool operator!=(Index o) const { return i != o.i; }
    };
    uint32_t first, last;
    Index begin() const { return {first}; }
    Index end() const { return {last}; }
  };
  TriangleRange trianglesOf(uint32_t element) const { return {firstTriangle_[element], firstTriangle_[element + 1]}; }
  std::array<Vec3, 3> positions(uint32_t triangle) const;
  Vec3 normal(uint32_t triangle) const;  // unit
  // Index (0..2) of the corner of `triangle` at the position of node `node`, or -1.
  int cornerAt(uint32_t triangle, uint32_t node) const;

  struct Location {
    uint32_t triangle = 0;
    Vec3 barycentric{1.0, 0.0, 0.0};  // of x projected onto the triangle's plane
  };
  // The triangle of `element` that contains x (the least-outside one if none does).
  Location locate(uint32_t element, const Vec3& x) const;

 private:
  const RadiosityMesh& mesh_;
  std::shared_ptr<const MeshTopology> topology_;
  std::vector<SurfaceTriangle> triangles_;
  std::vector<uint32_t> firstTriangle_;  // per element, and one past the last: where its triangles start
};

}  // namespace radview
