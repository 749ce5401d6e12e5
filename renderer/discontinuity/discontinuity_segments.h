#pragma once
// From the event segments on one receiver to a planar straight-line graph the constrained
// Delaunay mesher accepts without degenerate slivers: collinear overlapping segments merged
// (the strongest continuity order wins where they overlap), endpoints closer than a tolerance
// made one point, an endpoint near another segment put exactly on it (the stronger segment's
// line stays straight), segments split where they cross, where another's endpoint lies on
// them and where they meet the boundary (which gets those points as vertices). Without this, two
// events computed along the same line in different ways (an EV and a VE wedge of parallel
// edges) would differ by rounding and leave triangles 1e-16 wide.
#include "core/limits.h"
#include "discontinuity/discontinuity_events.h"
#include "geom/constrained_mesh_cgal.h"

#include <cstddef>
#include <vector>

namespace radview {

struct SegmentArrangement {
  PlanarGraph graph;                     // boundary ring (from the outline) and the segments
  std::vector<Continuity> order;         // per graph segment
  std::vector<int> outlinePoint;         // per outline vertex, its graph point
  size_t mergedSegments[3] = {0, 0, 0};  // per order (C-1, C0, C1): after merging, before splitting
  size_t dropped = 0;                    // merged segments past kMaxSegmentsPerPolygon
};

// `outline`: the polygon, counter-clockwise; `segments` inside it (discontinuity_events.h);
// `tolerance`: the snapping distance (discontinuity_mesher.cpp: rounding level, raised to a
// thousandth of an element). Outline vertices keep their exact positions; other points snap
// to them; merged segments lying along a boundary edge are dropped (the edge is there).
SegmentArrangement arrangeSegments(const std::vector<Vec2>& outline, const std::vector<EventSegment>& segments,
                                   double tolerance);

}  // namespace radview
