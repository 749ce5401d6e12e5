#include "discontinuity/discontinuity_mesher.h"

#include "core/disjoint_sets.h"
#include "core/error.h"
#include "discontinuity/critical_lines.h"
#include "discontinuity/discontinuity_events.h"
#include "discontinuity/discontinuity_segments.h"
#include "geom/constrained_mesh_cgal.h"
#include "geom/polygon.h"
#include "mesh/uniform_mesher.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

namespace radview {

namespace {

// Triangles per unit area that a refinement to maximum edge length `size` gives, about: its
// triangles are near-equilateral with edges between size / 2 and size.
double trianglesPerArea(double size) { return 1.0 / (0.25 * size * size); }

// Appends one polygon's constrained mesh to `mesh`. Nodes: one per (vertex, fan of triangles
// around it not separated by a C-1 edge), so the two sides of a C-1 edge get their own nodes
// and a C-1 polyline ending inside the polygon closes on a shared node (duplicated
// nodes across C-1 edges: Salesin, Lischinski, DeRose 1992).
void appendPolygon(RadiosityMesh& mesh, const ConstrainedMesh& cm, const SegmentArrangement& arrangement,
                   const std::vector<Vec3>& vertices, const PlaneFrame& frame, int surface, int material,
                   DiscontinuityMeshReport& report) {
  std::map<std::pair<int, int>, Continuity> edgeOrder;  // constrained triangle edges, tagged
  for (size_t s = 0; s < cm.segmentEdges.size(); ++s)
    for (const auto& [a, b] : cm.segmentEdges[s]) {
      auto [it, added] = edgeOrder.emplace(std::minmax(a, b), arrangement.order[s]);
      if (!added && int(arrangement.order[s]) < int(it->second)) it->second = arrangement.order[s];
    }

  // Corner (t, k) is entry 3 t + k; corners of two triangles sharing an edge that is not C-1
  // are joined at both ends of that edge.
  const size_t triangles = cm.triangles.size();
  DisjointSets fans(3 * triangles);
  std::map<std::pair<int, int>, size_t> firstSide;  // edge -> corner entry of its first triangle
  for (size_t t = 0; t < triangles; ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = cm.triangles[t][k], b = cm.triangles[t][(k + 1) % 3];
      const auto key = std::minmax(a, b);
      auto [it, added] = firstSide.emplace(key, 3 * t + k);
      if (added) continue;
      auto order = edgeOrder.find(key);
      if (order != edgeOrder.end() && order->second == Continuity::Cm1) continue;
      // The other triangle's edge starts at corner `start` and ends at `end`; counter-clockwise
      // neighbours run it the other way, b -> a.
      const size_t u = it->second / 3, start = it->second, end = 3 * u + (it->second % 3 + 1) % 3;
      const bool reversed = cm.triangles[u][it->second % 3] == b;
      fans.join(3 * t + k, reversed ? end : start);
      fans.join(3 * t + (k + 1) % 3, reversed ? start : end);
    }

  std::vector<int> outlineIndex(cm.vertices.size(), -1);  // vertex -> polygon vertex, if one
  for (size_t v = 0; v < cm.vertices.size(); ++v)
    if (cm.inputPoint[v] >= 0)
      for (size_t i = 0; i < arrangement.outlinePoint.size(); ++i)
        if (arrangement.outlinePoint[i] == cm.inputPoint[v]) outlineIndex[v] = int(i);
  std::vector<uint32_t> nodeOfFan(3 * triangles, UINT32_MAX);
  auto node = [&](size_t t, int k) {
    const size_t fan = fans.find(3 * t + k);
    if (nodeOfFan[fan] == UINT32_MAX) {
      const int v = cm.triangles[t][k];
      Node n;
      const Vec2 p = cm.vertices[v];
      n.position = outlineIndex[v] >= 0 ? vertices[outlineIndex[v]] : frame.origin + p.x * frame.u + p.y * frame.v;
      nodeOfFan[fan] = uint32_t(mesh.nodes.size());
      mesh.nodes.push_back(n);
    }
    return nodeOfFan[fan];
  };
  for (size_t t = 0; t < triangles; ++t) {
    Element e;
    e.corners = {node(t, 0), node(t, 1), node(t, 2)};
    e.surface = surface;
    e.material = material;
    mesh.elements.push_back(std::move(e));
  }
  // One DiscontinuityEdge per tagged edge, with the nodes of its first side.
  for (const auto& [key, order] : edgeOrder) {
    if (order == Continuity::C1) continue;
    auto side = firstSide.find(key);
    if (side == firstSide.end()) continue;  // a constrained edge outside the polygon: none
    const size_t t = side->second / 3;
    const int k = int(side->second % 3);
    mesh.discontinuities.push_back({node(t, k), node(t, (k + 1) % 3), order});
    ++(order == Continuity::Cm1 ? report.edgesCm1 : report.edgesC0);
  }
}

}  // namespace

RadiosityMesh meshWithDiscontinuities(const Scene& scene, double elementSize, DiscontinuityMeshReport* report) {
  if (!(elementSize > 0.0) || !std::isfinite(elementSize)) {
    std::ostringstream os;
    os << "element size " << elementSize << " is not a positive finite length";
    throw Error(os.str());
  }
  double totalArea = 0.0;
  for (const Polygon& p : scene.polygons) totalArea += area(p.vertices);
  const double estimate = totalArea * trianglesPerArea(elementSize);
  if (estimate > double(kMaxMeshElements)) {
    std::ostringstream os;
    os << "element size " << elementSize << " gives about " << std::llround(estimate)
       << " elements, more than radview's limit of " << kMaxMeshElements << "; an element size of "
       << elementSize * std::sqrt(estimate / double(kMaxMeshElements)) * 1.01 << " or more fits";
    throw Error(os.str());
  }

  DiscontinuityMeshReport local;
  DiscontinuityMeshReport& r = report ? *report : local;
  r = DiscontinuityMeshReport();
  EventCounts counts;
  const CriticalLinesByRays criticalLines(scene);
  const std::vector<std::vector<EventSegment>> events = findDiscontinuityEvents(scene, counts, &criticalLines);
  r.hiddenParts = counts.hiddenParts;
  r.wedgesHidden = counts.wedgesHidden;
  r.partsCut = counts.partsCut;
  r.contactEvents = counts.found[int(EventKind::Contact)];
  r.emitterVertexEvents = counts.found[int(EventKind::EmitterVertexOccluderEdge)];
  r.occluderVertexEvents = counts.found[int(EventKind::OccluderVertexEmitterEdge)];
  r.eventsFound = r.contactEvents + r.emitterVertexEvents + r.occluderVertexEvents;
  for (size_t inserted : counts.inserted) r.eventsInserted += inserted;
  r.occludersSkipped = counts.triplesCulled;
  r.occludersKept = counts.triplesKept;

  RadiosityMesh mesh;
  mesh.materials = scene.materials;
  for (size_t p = 0; p < scene.polygons.size(); ++p) {
    const Polygon& polygon = scene.polygons[p];
    if (polygon.vertices.size() < 3 || unitNormal(polygon.vertices) == Vec3(0.0)) continue;
    const PlaneFrame frame = planeFrame(polygon.vertices);
    std::vector<Vec2> outline;
    Bounds bounds;
    for (const Vec3& v : polygon.vertices) {
      outline.push_back(frame.project(v));
      bounds.extend(v);
    }
    // Snapping distance: rounding level (kEventTolerance of the polygon), raised to a thousandth
    // of an element so that events closer than that (the two long edges of a sliver occluder)
    // become one line instead of forcing the refinement down to their spacing; never more than
    // a thousandth of the polygon.
    const double diagonal = bounds.diagonal();
    const double tolerance = std::min(std::max(kEventTolerance * diagonal, 1e-3 * elementSize), 1e-3 * diagonal);
    const SegmentArrangement arrangement = arrangeSegments(outline, events[p], tolerance);
    r.segmentsCm1 += arrangement.mergedSegments[0];
    r.segmentsC0 += arrangement.mergedSegments[1];
    r.segmentsC1 += arrangement.mergedSegments[2];
    r.segmentsDropped += arrangement.dropped;
    // A generous cap on refinement (several times the expected count): small angles between
    // constraints make Delaunay refinement add points near them; never without bound.
    const size_t maxVertices = size_t(8.0 * area(polygon.vertices) * trianglesPerArea(elementSize)) +
                               8 * arrangement.graph.points.size() + 1000;
    const ConstrainedMesh cm = constrainedDelaunayMesh(arrangement.graph, elementSize, maxVertices);
    if (!cm.refinementComplete) ++r.refinementCapped;
    appendPolygon(mesh, cm, arrangement, polygon.vertices, frame, int(p), polygon.material, r);
  }
  r.segmentsInserted = r.segmentsCm1 + r.segmentsC0 + r.segmentsC1;
  r.elements = mesh.elements.size();
  r.nodes = mesh.nodes.size();
  return mesh;
}

std::ostream& operator<<(std::ostream& os, const DiscontinuityMeshReport& r) {
  os << "discontinuity meshing: " << r.eventsFound << " events found (" << r.contactEvents << " D0 contacts, "
     << r.emitterVertexEvents << " EV, " << r.occluderVertexEvents << " VE), " << r.eventsInserted << " inserted; "
     << r.occludersSkipped << " (emitter, occluder, receiver) triples culled, " << r.occludersKept << " kept\n"
     << "  wedge pieces hidden by other occluders, left out: " << r.hiddenParts << " (" << r.wedgesHidden
     << " wedges wholly); hidden in part, cut: " << r.partsCut << "\n"
     << "  " << r.segmentsInserted << " segments (C-1 " << r.segmentsCm1 << ", C0 " << r.segmentsC0 << ", C1 "
     << r.segmentsC1 << ")";
  if (r.segmentsDropped > 0) os << ", " << r.segmentsDropped << " dropped past the per-polygon cap";
  os << "; discontinuity edges C-1 " << r.edgesCm1 << ", C0 " << r.edgesC0 << "\n  " << r.elements << " elements, "
     << r.nodes << " nodes";
  if (r.refinementCapped > 0) os << "; refinement stopped at the vertex cap on " << r.refinementCapped << " polygons";
  return os;
}

}  // namespace radview
