#pragma once
// The critical curves of direct illumination from polygonal area emitters, on each receiver:
// where the emitter's visible part changes its combinatorial structure, the illumination has
// a discontinuity in value or derivative (Heckbert 1992, "Discontinuity meshing for
// radiosity"; Lischinski, Tampieri, Greenberg 1992, "Discontinuity meshing for accurate
// radiosity"). Pure geometry, no CGAL: the segments found here are merged and meshed by
// discontinuity_segments.h and discontinuity_mesher.h.
//
// Continuity orders (the rule implemented, after Heckbert 1992):
//  - D0, C-1: a polygon touching or passing through the receiver (a box standing on the floor)
//    cuts the light off on one side at once.
//  - EV (emitter vertex e, occluder edge) and VE (occluder vertex v, emitter edge) wedges:
//    crossing one, a vertex of the visible emitter polygon appears or vanishes; the
//    illumination (a sum over the visible polygon's edges, Lambert's formula) has a jump in
//    its second derivative: D2, tagged nothing (C1) but inserted, so the mesh follows it.
//  - The same wedge is D1 (tagged C0) when its plane also contains a second edge at its apex
//    side: an emitter edge at e (EV) or an occluder edge at v (VE), i.e. an occluder edge
//    parallel to (or coplanar with) an emitter edge. Crossing it a whole edge of the visible
//    polygon appears at once, so the first derivative jumps (Heckbert's EE degeneracy; the
//    penumbra and umbra boundaries of parallel squares).
#include "geom/plane_segments.h"
#include "mesh/radiosity_mesh.h"
#include "scene/scene.h"

#include <cstddef>
#include <vector>

namespace radview {

enum class EventKind { Contact, EmitterVertexOccluderEdge, OccluderVertexEmitterEdge };

// One critical segment on one receiver, in the receiver's planeFrame coordinates, inside it.
struct EventSegment {
  Vec2 a, b;
  Continuity order = Continuity::C1;
  EventKind kind = EventKind::Contact;
  // A contact's clearance: 0 where the polygons touch; for a flat footprint (a polygon lying a
  // hair in front of the receiver, findContacts), its height above the receiver's plane.
  double gap = 0.0;
};

struct EventCounts {
  size_t found[3] = {0, 0, 0};     // per EventKind: considered after culling
  size_t inserted[3] = {0, 0, 0};  // per EventKind: left at least one segment on the receiver
  size_t triplesCulled = 0;        // (emitter, occluder, receiver) triples that cannot shadow
  size_t triplesKept = 0;
  // Wedge pieces on a receiver that other occluders hide (CriticalLineTest): the pieces left
  // out, the wedges of which nothing was left, and the pieces hidden in part, cut to their
  // clear parts.
  size_t hiddenParts = 0, wedgesHidden = 0, partsCut = 0;
};

// Whether the critical line of a wedge event is clear at one receiver point: the line from the
// point x on the receiver (whose lit side faces xNormal) through the occluder's vertex or edge
// point q to the emitter's point s (on its side facing sNormal). Where something else blocks
// it, the emitter's visible part does not change its structure there, and the wedge is no
// discontinuity (Lischinski, Tampieri, Greenberg 1992: only unoccluded wedge parts count).
struct CriticalLineTest {
  virtual ~CriticalLineTest() = default;
  virtual bool clear(const Vec3& x, const Vec3& xNormal, const Vec3& q, const Vec3& s, const Vec3& sNormal) const = 0;
  // How far from the true place where the answer changes along a receiver the test's own
  // change can lie (a length); a piece cut there is put on another segment this close.
  virtual double precision() const = 0;
};

// A relative tolerance: lengths below this times a polygon's size count as zero, points this
// close (relative) count as one. Far above rounding (1e-16), far below any meaningful detail.
constexpr double kEventTolerance = 1e-7;

// The event segments on every scene polygon (index = polygon index), clipped to the polygon,
// with the parts lying on its boundary dropped (its edge already separates the elements).
// Emitters receive nothing and occlude nothing; every other non-degenerate polygon is a
// receiver and an occluder. Culled, per (emitter, occluder, receiver): an emitter not in
// front of the receiver or a receiver not in front of the emitter; an occluder entirely
// behind the emitter's plane, entirely behind the receiver's plane, not below every emitter
// vertex (measured from the receiver), not nearer the emitter than some receiver point; or
// whose shadow's bounding box (vertices projected from emitter vertices) misses the
// receiver's. With `criticalLines`, a piece of a wedge (EV or VE) on the receiver whose critical
// line is blocked at each of kCriticalLineSamples points along it is left out, and one blocked
// at some of them is cut to its clear parts; a cut end within the test's precision of another
// segment on the receiver (what blocks the line, often an occluder's footprint) is put exactly
// on it, the strongest and then the nearest. Without it every piece is kept whole.
std::vector<std::vector<EventSegment>> findDiscontinuityEvents(const Scene& scene, EventCounts& counts,
                                                               const CriticalLineTest* criticalLines = nullptr);
constexpr int kCriticalLineSamples = 32;

// The D0 contact segments alone, as findDiscontinuityEvents finds them, on every polygon,
// emitters included (an emitting floor under a block is covered as any other). Besides the
// lines where a polygon touches or crosses the receiver's plane, the outline of a flat
// footprint: a polygon lying wholly in front of the receiver within kFlatFootprintGap of its
// own size (a light fitted a hair under the ceiling). Behind it the receiver sees almost
// nothing; at its outline, half of its hemisphere; ten gaps out, all but 0.25 % (a half-plane
// at height g and distance d covers (1 - d / sqrt(d^2 + g^2)) / 2 of the cosine-weighted
// hemisphere). To any element much larger than the gap that is a step, C-1, as a contact is.
std::vector<std::vector<EventSegment>> findContacts(const Scene& scene);
constexpr double kFlatFootprintGap = 0.01;

}  // namespace radview
