#pragma once
// The seam to CGAL: the only function of radview_cgal, the one translation unit that
// includes CGAL headers (slow to compile, -frounding-math). Callers use triangulatePolygon.
#include "core/types.h"

#include <array>
#include <optional>
#include <vector>

namespace radview {

// Constrained Delaunay triangulation (CGAL, exact predicates) of a simple polygon given in
// counter-clockwise order in its plane. Returns the triangles inside it as indices into
// `polygon`, counter-clockwise, exactly polygon.size() - 2 of them. Throws Error if two
// vertices coincide or an edge touches or crosses another (the polygon is not simple).
std::vector<std::array<int, 3>> constrainedDelaunayTriangulation(const std::vector<Vec2>& polygon);

// The same for a strictly convex quadrilateral (counter-clockwise), without building a
// triangulation: what constrainedDelaunayTriangulation returns for it, the same triangles in the
// same order, from the same exact predicates. Nothing for any other four points.
std::optional<std::array<std::array<int, 3>, 2>> convexQuadDelaunay(const std::array<Vec2, 4>& quad);

}  // namespace radview
