#pragma once
// The seam to CGAL's 2D mesh generator (Mesh_2): a polygon with constraint segments inside it,
// as a constrained Delaunay triangulation refined to a maximum edge length. The discontinuity
// mesher (discontinuity/discontinuity_mesher.h) builds on it; this is a radview_cgal translation unit.
#include "core/types.h"

#include <array>
#include <cstddef>
#include <vector>

namespace radview {

// A planar straight-line graph: a simple boundary ring and segments inside it, all between
// indexed points. Segments should touch each other and the boundary only at shared points
// (discontinuity/discontinuity_segments.h arranges that); a residual crossing is still split at a
// constructed point (CGAL's Exact_predicates_tag), never refused.
struct PlanarGraph {
  std::vector<Vec2> points;
  std::vector<int> boundary;                 // counter-clockwise ring of point indices
  std::vector<std::array<int, 2>> segments;  // constraints, point indices
};

struct ConstrainedMesh {
  std::vector<Vec2> vertices;
  std::vector<int> inputPoint;                // per vertex: its index in PlanarGraph::points, or -1
  std::vector<std::array<int, 3>> triangles;  // vertex indices, counter-clockwise
  // Per input segment, the triangle edges (vertex pairs) that cover it, in order from its
  // first point to its second: refinement splits a constraint into several edges.
  std::vector<std::vector<std::array<int, 2>>> segmentEdges;
  bool refinementComplete = true;  // false when maxVertices stopped the refinement early
};

// Constrained Delaunay triangulation of `graph` (exact predicates), refined by Delaunay
// refinement (CGAL Delaunay_mesher_2, Ruppert/Shewchuk) until no triangle inside the boundary
// has an edge longer than maxEdgeLength or a shape worse than CGAL's default bound 0.125
// (minimum angle about 20.7 degrees), or until the triangulation has maxVertices vertices.
// Only the triangles inside the boundary are returned.
ConstrainedMesh constrainedDelaunayMesh(const PlanarGraph& graph, double maxEdgeLength, size_t maxVertices);

}  // namespace radview
