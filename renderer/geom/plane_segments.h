#pragma once
// Segments and polygons in a plane (2D coordinates, such as a polygon's PlaneFrame): the parts of
// a segment inside a simple polygon, concave included, and the distances and snapping that
// discontinuity meshing uses to put a segment's end exactly on another's line.
#include "core/types.h"

#include <vector>

namespace radview {

// The parts of segment a-b inside a polygon (any simple polygon, concave included), as
// parameter intervals [t0, t1] of a + t (b - a), sorted; parts within `tolerance` of the
// boundary and pieces shorter than it are left out.
struct ParameterInterval {
  double t0 = 0.0, t1 = 0.0;
};
std::vector<ParameterInterval> clipSegmentToPolygon(const Vec2& a, const Vec2& b, const std::vector<Vec2>& polygon,
                                                    double tolerance);

// Distance from p to the segment a-b.
double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b);

// Where a segment ending at `end` (its other end `from`) ends when put exactly on the line
// through a and b: where its own line meets that line, so it stays on its own line, or, for
// lines too near parallel to meet within `reach` of `end`, the projection of `end`.
Vec2 endOntoLine(const Vec2& from, const Vec2& end, const Vec2& a, const Vec2& b, double reach);

// Distance from p to the nearest point of the polygon's boundary.
double distanceToPolygonBoundary(const Vec2& p, const std::vector<Vec2>& polygon);

// Whether p is inside the polygon by the crossing-number test; for points on or near the boundary
// either answer can come: callers test distanceToPolygonBoundary first.
bool strictlyInsidePolygon(const Vec2& p, const std::vector<Vec2>& polygon);

}  // namespace radview
