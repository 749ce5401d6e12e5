#pragma once
// The initial mesh of a scene with its shadow boundaries built in (Heckbert 1992; Lischinski,
// Tampieri, Greenberg 1992): every polygon becomes a constrained Delaunay triangulation whose
// constrained edges follow the discontinuities of direct illumination
// (discontinuity_events.h), tagged with their continuity order for the C1 interpolants'
// relaxation (Salesin, Lischinski, DeRose 1992).
#include "mesh/radiosity_mesh.h"
#include "scene/scene.h"

#include <cstddef>
#include <ostream>

namespace radview {

struct DiscontinuityMeshReport {
  size_t eventsFound = 0;       // EV/VE wedges and D0 contacts considered after culling
  size_t eventsInserted = 0;    // those that left at least one segment on a receiver
  size_t segmentsInserted = 0;  // constraint segments after clipping and merging collinear ones
  size_t occludersSkipped = 0;  // (emitter, occluder, receiver) triples culled
  size_t occludersKept = 0;     // triples whose wedges were computed
  // Wedge pieces whose critical line other occluders block (discontinuity_events.h): the
  // pieces left out, the wedges of which nothing was left, the pieces cut to their clear parts.
  size_t hiddenParts = 0, wedgesHidden = 0, partsCut = 0;
  // Found per kind: D0 contacts, EV wedges, VE wedges.
  size_t contactEvents = 0, emitterVertexEvents = 0, occluderVertexEvents = 0;
  // segmentsInserted by order: C-1 (D0), C0 (D1), C1 (D2, inserted untagged).
  size_t segmentsCm1 = 0, segmentsC0 = 0, segmentsC1 = 0;
  size_t segmentsDropped = 0;  // past kMaxSegmentsPerPolygon (discontinuity_segments.h)
  // Discontinuity edges of the mesh (element edges) per tag.
  size_t edgesCm1 = 0, edgesC0 = 0;
  size_t refinementCapped = 0;  // polygons whose refinement stopped at the vertex cap
  size_t elements = 0, nodes = 0;
};

// Meshes every scene polygon into triangles no larger than about elementSize, with the
// discontinuity segments on it as constrained edges, tagged as DiscontinuityEdges. The
// result keeps meshUniformly's contract (uniform_mesher.h): Element.surface is the polygon's
// index, material its material, mesh.materials the scene's, B zero, corners counter-clockwise
// about the polygon's normal, nodes never shared across polygons, validateMesh passes. Across
// a C-1 edge each side has its own nodes (at the same positions); C0 and C1 edges share them.
// Polygon vertices keep their exact positions; other nodes lie on the polygon's plane
// (planeFrame). Zero-area polygons get no elements. Throws Error for a size that is not
// positive and finite or that would give more than kMaxMeshElements elements.
// `report` may be null.
RadiosityMesh meshWithDiscontinuities(const Scene& scene, double elementSize, DiscontinuityMeshReport* report);

std::ostream& operator<<(std::ostream& os, const DiscontinuityMeshReport& report);

}  // namespace radview
