// CGAL Mesh_2 behind constrainedDelaunayMesh (see constrained_mesh_cgal.h).
#include "geom/constrained_mesh_cgal.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

namespace radview {

namespace {

// Where a vertex came from (its input point, -1 for a Steiner point of the refinement) and,
// once refined, its output index. Default-initialised: CGAL default-constructs the info of
// the vertices it inserts.
struct VertexInfo {
  int inputPoint = -1;
  int index = -1;
};

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, Kernel>;
using FaceBase = CGAL::Delaunay_mesh_face_base_2<Kernel, CGAL::Constrained_triangulation_face_base_2<Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// Exact_predicates_tag: a constraint crossing another is split at their (constructed)
// intersection instead of throwing; the callers avoid that case but must not fail on it.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Mesher = CGAL::Delaunay_mesher_2<Cdt, Criteria>;

Vec2 toVec2(const Kernel::Point_2& p) { return {p.x(), p.y()}; }

// The chain of constrained edges from `from` to `to`: refinement splits a constraint at
// points on it, and a residual crossing splits it at the crossing; at each vertex the chain
// goes on along the constrained edge that points most nearly at `to`.
std::vector<std::array<int, 2>> constraintChain(const Cdt& cdt, Cdt::Vertex_handle from, Cdt::Vertex_handle to) {
  std::vector<std::array<int, 2>> chain;
  Cdt::Vertex_handle current = from;
  const size_t maxSteps = cdt.number_of_vertices();
  while (current != to && chain.size() < maxSteps) {
    const Vec2 here = toVec2(current->point());
    const Vec2 towards = glm::normalize(toVec2(to->point()) - here);
    Cdt::Vertex_handle best;
    double bestCosine = 0.9;  // a constraint's pieces are collinear up to rounding
    Cdt::Edge_circulator edge = cdt.incident_edges(current), done = edge;
    if (edge == nullptr) break;
    do {
      if (cdt.is_infinite(edge) || !cdt.is_constrained(*edge)) continue;
      const Cdt::Face_handle face = edge->first;
      Cdt::Vertex_handle other = face->vertex(Cdt::cw(edge->second));
      if (other == current) other = face->vertex(Cdt::ccw(edge->second));
      const double cosine = glm::dot(glm::normalize(toVec2(other->point()) - here), towards);
      if (cosine > bestCosine) {
        bestCosine = cosine;
        best = other;
      }
    } while (++edge != done);
    if (best == Cdt::Vertex_handle()) break;  // cannot happen for an inserted constraint
    chain.push_back({current->info().index, best->info().index});
    current = best;
  }
  return chain;
}

}  // namespace

ConstrainedMesh constrainedDelaunayMesh(const PlanarGraph& graph, double maxEdgeLength, size_t maxVertices) {
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles(graph.points.size());
  for (size_t i = 0; i < graph.points.size(); ++i) {
    handles[i] = cdt.insert(Kernel::Point_2(graph.points[i].x, graph.points[i].y));
    if (handles[i]->info().inputPoint < 0) handles[i]->info().inputPoint = int(i);
  }
  const size_t ring = graph.boundary.size();
  for (size_t i = 0; i < ring; ++i) {
    const auto a = handles[graph.boundary[i]], b = handles[graph.boundary[(i + 1) % ring]];
    if (a != b) cdt.insert_constraint(a, b);
  }
  for (const auto& [a, b] : graph.segments)
    if (handles[a] != handles[b]) cdt.insert_constraint(handles[a], handles[b]);

  // The domain is what the boundary encloses: faces reachable from the infinite face without
  // crossing a constraint are outside (the mesher's default marking, no seeds); segments
  // inside never reach the boundary's outside.
  Mesher mesher(cdt, Criteria(0.125, maxEdgeLength));
  mesher.init();
  ConstrainedMesh mesh;
  while (!mesher.is_refinement_done()) {
    if (cdt.number_of_vertices() >= maxVertices) {
      mesh.refinementComplete = false;
      break;
    }
    mesher.step_by_step_refine_mesh();
  }

  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    v->info().index = int(mesh.vertices.size());
    mesh.vertices.push_back(toVec2(v->point()));
    mesh.inputPoint.push_back(v->info().inputPoint);
  }
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->is_in_domain())
      mesh.triangles.push_back({f->vertex(0)->info().index, f->vertex(1)->info().index, f->vertex(2)->info().index});
  mesh.segmentEdges.reserve(graph.segments.size());
  for (const auto& [a, b] : graph.segments)
    mesh.segmentEdges.push_back(handles[a] == handles[b] ? std::vector<std::array<int, 2>>{}
                                                         : constraintChain(cdt, handles[a], handles[b]));
  return mesh;
}

}  // namespace radview
