#pragma once
// The seam to CGAL's planar convex hull (a translation unit of radview_cgal, see
// triangulate_cgal.h for why CGAL stays behind such seams).
#include "core/types.h"

#include <vector>

namespace radview {

// The convex hull of points in a plane (CGAL::convex_hull_2, exact predicates): indices into
// `points` of its corners, counter-clockwise, collinear points left out. Fewer than three
// indices when the points are all on one line.
std::vector<int> convexHull2(const std::vector<Vec2>& points);

}  // namespace radview
