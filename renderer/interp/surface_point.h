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

// The closest point of any element to p: the element with the least distance, the lowest
// element index among equals. By brute force over every element, the definition SurfaceLocator
// (interp/surface_locator.h) answers from a spatial index. Throws Error for a mesh without
// elements.
SurfacePoint nearestSurfacePoint(const RadiosityMesh& mesh, const Vec3& p);

// Closest point to p on triangle (a, b, c): its projection when inside, else the closest
// point of the nearest edge.
Vec3 closestOnTriangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p);

// b0 c0 + b1 c1 + b2 c2 for the element's first three corners c0..c2: barycentric in a
// triangle, an affine frame in a quad or polygon (so every point of it can be named).
Vec3 pointFromBarycentric(const RadiosityMesh& mesh, uint32_t element, const Vec3& b);

}  // namespace radview
