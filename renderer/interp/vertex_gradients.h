#pragma once
// The "normals" of the radiosity surface at the triangle corners (C&W §9.2.2, first step of
// the Clough-Tocher construction, fig. 9.10), as surface gradients: one per triangle corner
// and channel. Corners around a vertex that are joined by C1 edges form a sector and share
// one gradient; across C0 and C-1 edges each side has its own (Salesin et al. 1992).
#include "interp/surface_triangulation.h"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace radview {

// gradients[triangle][corner][channel], world space, in the triangle's plane. The corners of
// a sector share one stored gradient: about a quarter of the memory of one per corner (a
// million-element mesh has two million corners, 72 bytes of gradient each).
class CornerGradients {
 public:
  using Gradient = std::array<Vec3, 3>;  // [channel]
  CornerGradients() = default;
  // Corner c (= 3 triangle + k) has gradient gradients[sectorOf[c]].
  CornerGradients(std::vector<uint32_t> sectorOf, std::vector<Gradient> gradients)
      : sectorOf_(std::move(sectorOf)), gradients_(std::move(gradients)) {}
  size_t size() const { return sectorOf_.size() / 3; }  // triangles
  std::array<Gradient, 3> operator[](size_t triangle) const {
    const uint32_t* s = &sectorOf_[3 * triangle];
    return {gradients_[s[0]], gradients_[s[1]], gradients_[s[2]]};
  }

 private:
  std::vector<uint32_t> sectorOf_;
  std::vector<Gradient> gradients_;
};

// From the mesh's stored gradients (projected into each triangle's plane) when it has them
// and useStored is set; otherwise estimated per sector:
//  - linear elements: the least-squares plane through the vertex and the other nodes of the
//    sector's triangles, passing through the vertex's value exactly;
//  - quadratic elements: per element, parabolas along its two edges at the vertex through
//    the vertex, mid-edge and far vertex values (fig. 9.10), the two slopes giving the
//    gradient; averaged over the sector's elements.
// Degenerate neighbourhoods get the minimum-norm least-squares gradient: neighbours all on
// one line through the vertex fix only the component along it, and a vertex with no usable
// neighbour gets 0. Never NaN for finite input.
// Then, at every C0 edge, the gradients of the two sectors it separates are made to agree in
// their component along the edge (the average of the two), so that B stays continuous along
// it (Salesin et al. 1992, "adjusting the computed normals ... until their components along
// the element are the same"); each sector keeps its other component.
CornerGradients vertexGradients(const SurfaceTriangulation& surface, bool useStored);

}  // namespace radview
