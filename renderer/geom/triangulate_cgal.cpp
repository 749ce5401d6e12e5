// The only translation unit that includes CGAL (see triangulate_cgal.h).
#include "geom/triangulate_cgal.h"

#include "core/error.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <queue>
#include <string>

namespace radview {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
// Vertex info: the index of the input vertex. Face info: nesting level, -1 until marked.
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using FaceBase =
    CGAL::Constrained_triangulation_face_base_2<Kernel, CGAL::Triangulation_face_base_with_info_2<int, Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// No_constraint_intersection_tag: crossing edges throw instead of being split at a new vertex.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::No_constraint_intersection_tag>;

[[noreturn]] void notSimple(const std::string& why) { throw Error("polygon is not simple: " + why); }

// Nesting level of every face: 0 for faces reachable from the infinite face without crossing
// a polygon edge, +1 per polygon edge crossed. Faces at odd levels are inside.
void markNestingLevels(Cdt& cdt) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::queue<Cdt::Face_handle> nextLevel;
  nextLevel.push(cdt.infinite_face());
  for (int level = 0; !nextLevel.empty(); ++level) {
    std::queue<Cdt::Face_handle> current;
    std::swap(current, nextLevel);
    while (!current.empty()) {
      Cdt::Face_handle f = current.front();
      current.pop();
      if (f->info() != -1) continue;
      f->info() = level;
      for (int i = 0; i < 3; ++i) {
        Cdt::Face_handle across = f->neighbor(i);
        if (across->info() != -1) continue;
        (cdt.is_constrained(Cdt::Edge(f, i)) ? nextLevel : current).push(across);
      }
    }
  }
}

}  // namespace

std::vector<std::array<int, 3>> constrainedDelaunayTriangulation(const std::vector<Vec2>& polygon) {
  const int n = static_cast<int>(polygon.size());
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles(n);
  for (int i = 0; i < n; ++i) {
    handles[i] = cdt.insert(Kernel::Point_2(polygon[i].x, polygon[i].y));
    // A repeated point adds no vertex: CGAL returns the existing one, whose info names it.
    if (cdt.number_of_vertices() != static_cast<size_t>(i) + 1)
      notSimple("vertices " + std::to_string(handles[i]->info()) + " and " + std::to_string(i) + " coincide");
    handles[i]->info() = i;
  }
  try {
    for (int i = 0; i < n; ++i) cdt.insert_constraint(handles[i], handles[(i + 1) % n]);
  } catch (const Cdt::Intersection_of_constraints_exception&) {
    notSimple("two edges cross or overlap");
  }
  // A vertex lying on another edge splits that constraint: the edge is then missing.
  for (int i = 0; i < n; ++i)
    if (!cdt.is_edge(handles[i], handles[(i + 1) % n]))
      notSimple("vertex lies on edge " + std::to_string(i) + " -> " + std::to_string((i + 1) % n));

  markNestingLevels(cdt);
  std::vector<std::array<int, 3>> triangles;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info() % 2 == 1) triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  // A simple polygon of n vertices has n - 2 triangles; anything else means it was not simple.
  if (static_cast<int>(triangles.size()) != n - 2)
    notSimple(std::to_string(triangles.size()) + " triangles inside instead of " + std::to_string(n - 2));
  return triangles;
}

std::optional<std::array<std::array<int, 3>, 2>> convexQuadDelaunay(const std::array<Vec2, 4>& quad) {
  std::array<Kernel::Point_2, 4> p;
  for (int i = 0; i < 4; ++i) p[i] = Kernel::Point_2(quad[i].x, quad[i].y);
  for (int i = 0; i < 4; ++i)
    if (CGAL::orientation(p[i], p[(i + 1) % 4], p[(i + 2) % 4]) != CGAL::LEFT_TURN) return std::nullopt;
  // CGAL inserts 0, 1, 2, then 3 outside that triangle, and flips the diagonal 0-2 to 1-3 when
  // 3 is inside the circle through 0, 1, 2. On that circle it breaks the tie by a symbolic
  // perturbation (Triangulation_2::side_of_oriented_circle), which for a convex quad keeps the
  // diagonal that avoids the lexicographically largest corner (x, then y).
  bool flip = false;
  switch (CGAL::side_of_oriented_circle(p[0], p[1], p[2], p[3])) {
    case CGAL::ON_POSITIVE_SIDE: flip = true; break;
    case CGAL::ON_NEGATIVE_SIDE: flip = false; break;
    default: {
      int largest = 0;
      for (int i = 1; i < 4; ++i)
        if (CGAL::compare_xy(p[i], p[largest]) == CGAL::LARGER) largest = i;
      flip = largest == 0 || largest == 2;
    }
  }
  // The faces in the order CGAL's face container lists them after those steps.
  if (flip) return std::array<std::array<int, 3>, 2>{{{3, 1, 2}, {3, 0, 1}}};
  return std::array<std::array<int, 3>, 2>{{{0, 1, 2}, {3, 0, 2}}};
}

}  // namespace radview
