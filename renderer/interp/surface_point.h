#pragma once
// Where the user's points are on the mesh: the nearest element to a world-space point, or
// the point given by barycentric coordinates in an element.
#include "mesh/radiosity_mesh.h"

#include <cstdint>

namespace radview {

struct SurfacePoint {
  uint32_t element = 0;
  Vec3 x{0.0};            // on the element
  double distance = 0.0;  // from the point asked for to x
};

// The closest point of any element to p (brute force over elements: meant for sampling a
// handful of points, not for rendering). Throws Error for a mesh without elements.
SurfacePoint nearestSurfacePoint(const RadiosityMesh& mesh, const Vec3& p);

// b0 c0 + b1 c1 + b2 c2 for the element's first three corners c0..c2: barycentric in a
// triangle, an affine frame in a quad or polygon (so every point of it can be named).
Vec3 pointFromBarycentric(const RadiosityMesh& mesh, uint32_t element, const Vec3& b);

}  // namespace radview
