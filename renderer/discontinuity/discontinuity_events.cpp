#include "discontinuity/discontinuity_events.h"

#include "geom/plane_segments.h"
#include "geom/polygon.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace radview {

namespace {

// A scene polygon as the event search sees it: its plane, its outline in that plane, its size.
struct PolygonGeometry {
  bool valid = false;  // false for a degenerate polygon (no plane)
  PlaneFrame frame;
  std::vector<Vec2> outline;
  Bounds bounds;
  double size = 0.0;  // bounding-box diagonal
  double tolerance = 0.0;

  // Signed distance in front of the polygon's plane.
  double height(const Vec3& x) const { return glm::dot(frame.n, x - frame.origin); }
};

PolygonGeometry describe(const Polygon& polygon) {
  PolygonGeometry g;
  if (polygon.vertices.size() < 3 || unitNormal(polygon.vertices) == Vec3(0.0)) return g;
  g.valid = true;
  g.frame = planeFrame(polygon.vertices);
  for (const Vec3& p : polygon.vertices) {
    g.outline.push_back(g.frame.project(p));
    g.bounds.extend(p);
  }
  g.size = g.bounds.diagonal();
  g.tolerance = kEventTolerance * g.size;
  return g;
}

// Narrows [t0, t1] to where the linear function f(t) = f0 + t (f1 - f0) is >= 0.
void keepNonNegative(double f0, double f1, double& t0, double& t1) {
  if (f0 >= 0 && f1 >= 0) return;
  if (f0 < 0 && f1 < 0) {
    t1 = t0 - 1;  // empty
    return;
  }
  const double root = f0 / (f0 - f1);
  if (f0 < 0)
    t0 = std::max(t0, root);
  else
    t1 = std::min(t1, root);
}

// The point where the ray from `apex` through q meets the receiver's plane, beyond q; heights
// above that plane, hApex > hq >= 0 (similar triangles).
Vec3 projectFrom(const Vec3& apex, double hApex, const Vec3& q, double hq) {
  return apex + (hApex / (hApex - hq)) * (q - apex);
}

// True when the plane through `apex` with unit normal n contains one of the edges from apex
// to its neighbours in `ring` (apex = ring[i]): the wedge is then D1, not D2.
bool planeContainsEdgeAt(const Vec3& n, const std::vector<Vec3>& ring, size_t i) {
  const size_t count = ring.size();
  for (size_t j : {(i + 1) % count, (i + count - 1) % count}) {
    const Vec3 edge = ring[j] - ring[i];
    if (std::abs(glm::dot(n, edge)) <= kEventTolerance * glm::length(edge)) return true;
  }
  return false;
}

// Collects the clipped pieces of one event segment (3D, on the receiver's plane) on it.
// A wedge event's generator (Heckbert 1992): the critical line through a receiver point x runs
// from a point s of the emitter through a point q of the occluder. EV: s is the emitter vertex
// and q on the occluder edge; VE: q is the occluder vertex and s on the emitter edge.
struct Wedge {
  bool emitterVertex = true;
  Vec3 fixed{0.0}, edge0{0.0}, edge1{0.0};
  Vec3 emitterNormal{0.0};
};

// The point of the line through a and b nearest to the line p + t d (where the two meet, for
// lines in one plane).
Vec3 pointOnLineNearest(const Vec3& a, const Vec3& b, const Vec3& p, const Vec3& d) {
  const Vec3 e = b - a, w = a - p;
  const double dd = glm::dot(d, d), de = glm::dot(d, e), ee = glm::dot(e, e);
  const double denominator = dd * ee - de * de;
  if (!(std::abs(denominator) > 1e-300)) return a;
  return a + ((de * glm::dot(d, w) - dd * glm::dot(e, w)) / denominator) * e;
}

// A part of a wedge piece, as parameters along the wedge's segment; which of its ends were cut
// where the critical line's answer changes (the others are where the piece was clipped).
struct ClearPart {
  double t0 = 0.0, t1 = 0.0;
  bool cutAtStart = false, cutAtEnd = false;
};

class ReceiverEvents {
 public:
  ReceiverEvents(const PolygonGeometry& receiver, std::vector<EventSegment>& out, EventCounts& counts,
                 const CriticalLineTest* criticalLines)
      : receiver_(receiver), out_(out), counts_(counts), criticalLines_(criticalLines) {}

  // `gap`: a contact's clearance (EventSegment::gap).
  void add(const Vec3& x0, const Vec3& x1, EventKind kind, Continuity order, const Wedge* wedge = nullptr,
           double gap = 0.0) {
    ++counts_.found[int(kind)];
    const Vec2 a = receiver_.frame.project(x0), b = receiver_.frame.project(x1);
    const std::vector<ParameterInterval> clipped = clipSegmentToPolygon(a, b, receiver_.outline, receiver_.tolerance);
    std::vector<ClearPart> pieces;
    if (wedge && criticalLines_ && !clipped.empty()) {
      pieces = clearParts(a, b, clipped, *wedge);
      if (pieces.empty()) ++counts_.wedgesHidden;
    } else {
      for (const ParameterInterval& piece : clipped) pieces.push_back({piece.t0, piece.t1});
    }
    if (pieces.empty()) return;
    ++counts_.inserted[int(kind)];
    for (const ClearPart& piece : pieces) {
      if (piece.cutAtStart) cutEnds_.push_back({out_.size(), true});
      if (piece.cutAtEnd) cutEnds_.push_back({out_.size(), false});
      out_.push_back({a + piece.t0 * (b - a), a + piece.t1 * (b - a), order, kind, gap});
    }
  }

  // Puts each cut end that lies within the critical-line test's precision of another segment
  // on this receiver exactly on that segment's line (the strongest order, then the nearest):
  // it ends on what blocks its critical line, and the arrangement then splits that segment on
  // its own line (discontinuity_segments.h). Call once every event is added.
  void putCutEndsOnWhatBlocksThem() {
    if (!criticalLines_) return;
    const double reach = criticalLines_->precision();
    for (const auto& [index, atStart] : cutEnds_) {
      EventSegment& cut = out_[index];
      Vec2& end = atStart ? cut.a : cut.b;
      const Vec2 from = atStart ? cut.b : cut.a;
      const EventSegment* onto = nullptr;
      double nearest = reach;
      for (size_t j = 0; j < out_.size(); ++j) {
        const EventSegment& other = out_[j];
        const double d = distanceToSegment(end, other.a, other.b);
        if (j == index || d > reach) continue;
        if (!onto || int(other.order) < int(onto->order) || (other.order == onto->order && d < nearest)) {
          onto = &other;
          nearest = d;
        }
      }
      if (onto) end = endOntoLine(from, end, onto->a, onto->b, reach);
    }
  }

 private:
  // Whether the wedge's critical line is clear at the receiver point a + t (b - a).
  bool clearAt(const Vec2& a, const Vec2& b, double t, const Wedge& wedge) const {
    const PlaneFrame& f = receiver_.frame;
    const Vec2 p = a + t * (b - a);
    const Vec3 x = f.origin + p.x * f.u + p.y * f.v;
    const Vec3 q = wedge.emitterVertex ? pointOnLineNearest(wedge.edge0, wedge.edge1, x, wedge.fixed - x) : wedge.fixed;
    const Vec3 s = wedge.emitterVertex ? wedge.fixed : pointOnLineNearest(wedge.edge0, wedge.edge1, x, q - x);
    return criticalLines_->clear(x, f.n, q, s, wedge.emitterNormal);
  }

  // The parts of the pieces whose critical line is clear. Each piece is tested at
  // kCriticalLineSamples points; a piece blocked at every one is left out, one blocked at some
  // is cut where the answer changes between neighbouring samples (found by bisection), and the
  // ends beyond the first and last samples follow them. A cut end lies on what blocks the line
  // (typically another occluder's footprint or shadow edge on this receiver), to the test's
  // precision; putCutEndsOnWhatBlocksThem puts it exactly on that segment when it is one.
  std::vector<ClearPart> clearParts(const Vec2& a, const Vec2& b, const std::vector<ParameterInterval>& pieces,
                                    const Wedge& wedge) {
    std::vector<ClearPart> clear;
    const double length = glm::distance(a, b);
    for (const ParameterInterval& piece : pieces) {
      const double step = (piece.t1 - piece.t0) / kCriticalLineSamples;
      auto sample = [&](int k) { return piece.t0 + (k + 0.5) * step; };
      bool previous = clearAt(a, b, sample(0), wedge);
      bool anyClear = previous, anyBlocked = !previous;
      double start = piece.t0;
      bool startCut = false;
      const size_t before = clear.size();
      for (int k = 1; k < kCriticalLineSamples; ++k) {
        const bool now = clearAt(a, b, sample(k), wedge);
        if (now != previous) {
          const double change = transition(a, b, sample(k - 1), sample(k), previous, wedge);
          if (previous) {
            keep(clear, {start, change, startCut, true}, length);
          } else {
            start = change;
            startCut = true;
          }
        }
        anyClear |= now;
        anyBlocked |= !now;
        previous = now;
      }
      if (previous) keep(clear, {start, piece.t1, startCut, false}, length);
      if (!anyClear || clear.size() == before)
        ++counts_.hiddenParts;
      else if (anyBlocked)
        ++counts_.partsCut;
    }
    return clear;
  }

  // Where the line's answer changes between parameters t and u (clear at t when `clearAtT`):
  // bisection to a millionth of the sample spacing, the midpoint of the last bracket.
  double transition(const Vec2& a, const Vec2& b, double t, double u, bool clearAtT, const Wedge& wedge) const {
    for (int k = 0; k < 20; ++k) {
      const double middle = 0.5 * (t + u);
      if (clearAt(a, b, middle, wedge) == clearAtT)
        t = middle;
      else
        u = middle;
    }
    return 0.5 * (t + u);
  }

  // Appends the part unless it is shorter than the receiver's tolerance.
  void keep(std::vector<ClearPart>& parts, const ClearPart& part, double length) const {
    if ((part.t1 - part.t0) * length > receiver_.tolerance) parts.push_back(part);
  }

  const PolygonGeometry& receiver_;
  std::vector<EventSegment>& out_;
  EventCounts& counts_;
  const CriticalLineTest* criticalLines_;
  std::vector<std::pair<size_t, bool>> cutEnds_;  // (segment in out_, its start or its end)
};

// D0: where `other` touches or passes through the receiver's plane, inside `other` (Heckbert
// 1992, D0). Returns 3D segments on the receiver's plane; none for a coplanar polygon.
std::vector<std::array<Vec3, 2>> planeContact(const PolygonGeometry& receiver, const std::vector<Vec3>& vertices,
                                              const PolygonGeometry& other) {
  const double tolerance = kEventTolerance * std::max(receiver.size, other.size);
  std::vector<double> d;
  bool below = false, above = false, on = false;
  for (const Vec3& p : vertices) {
    double h = receiver.height(p);
    if (std::abs(h) <= tolerance) h = 0.0;
    d.push_back(h);
    below |= h < 0;
    above |= h > 0;
    on |= h == 0;
  }
  if (!on && !(below && above)) return {};
  if (!below && !above) return {};  // coplanar: it shares the plane, casts nothing across it
  const Vec3 line = glm::cross(receiver.frame.n, other.frame.n);
  if (glm::length(line) < kEventTolerance) return {};

  std::vector<Vec3> points;
  for (size_t i = 0; i < vertices.size(); ++i) {
    const size_t j = (i + 1) % vertices.size();
    if (d[i] == 0) points.push_back(vertices[i]);
    if (d[i] * d[j] < 0) points.push_back(vertices[i] + (d[i] / (d[i] - d[j])) * (vertices[j] - vertices[i]));
  }
  std::sort(points.begin(), points.end(),
            [&](const Vec3& a, const Vec3& b) { return glm::dot(a, line) < glm::dot(b, line); });
  // Consecutive crossings bound pieces inside or outside `other`; its midpoint tells which.
  std::vector<std::array<Vec3, 2>> pieces;
  for (size_t k = 0; k + 1 < points.size(); ++k) {
    if (glm::distance(points[k], points[k + 1]) <= tolerance) continue;
    const Vec2 middle = other.frame.project(0.5 * (points[k] + points[k + 1]));
    if (!strictlyInsidePolygon(middle, other.outline) && distanceToPolygonBoundary(middle, other.outline) > tolerance)
      continue;
    if (!pieces.empty() && glm::distance(pieces.back()[1], points[k]) <= tolerance)
      pieces.back()[1] = points[k + 1];
    else
      pieces.push_back({points[k], points[k + 1]});
  }
  return pieces;
}

// The outline of `other` where it lies flat in front of the receiver (findContacts): every
// vertex above the receiver's plane, none higher than kFlatFootprintGap of `other`'s size.
// Returns its edges dropped onto the receiver's plane, and the gap (the highest vertex's
// height); none for a polygon farther away, touching, or behind.
std::vector<std::array<Vec3, 2>> flatFootprint(const PolygonGeometry& receiver, const std::vector<Vec3>& vertices,
                                               const PolygonGeometry& other, double& gap) {
  gap = 0.0;
  std::vector<Vec3> dropped;
  for (const Vec3& p : vertices) {
    const double h = receiver.height(p);
    if (!(h > kEventTolerance * std::max(receiver.size, other.size) && h <= kFlatFootprintGap * other.size)) return {};
    gap = std::max(gap, h);
    dropped.push_back(p - h * receiver.frame.n);
  }
  std::vector<std::array<Vec3, 2>> edges;
  for (size_t i = 0; i < dropped.size(); ++i) edges.push_back({dropped[i], dropped[(i + 1) % dropped.size()]});
  return edges;
}

// The 2D bounding boxes of the receiver and of the occluder's shadow (every occluder vertex
// projected from every emitter vertex: the shadow lies in their convex hull, as the central
// projection from a point keeps convex sets convex) miss each other. Only when every
// projection exists: the occluder lies strictly between the emitter's lowest vertex and the
// receiver's plane; otherwise it cannot tell and says no.
bool shadowMissesReceiver(const PolygonGeometry& receiver, const std::vector<Vec3>& emitter,
                          const std::vector<double>& hEmitter, const std::vector<Vec3>& occluder,
                          const std::vector<double>& hOccluder, const std::vector<double>& hOccluderFromEmitter) {
  const double lowest = *std::min_element(hEmitter.begin(), hEmitter.end());
  for (size_t j = 0; j < occluder.size(); ++j)
    if (hOccluder[j] < 0 || hOccluder[j] >= lowest * (1 - 1e-6) || hOccluderFromEmitter[j] < 0) return false;
  Vec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (size_t i = 0; i < emitter.size(); ++i)
    for (size_t j = 0; j < occluder.size(); ++j) {
      const Vec2 x = receiver.frame.project(projectFrom(emitter[i], hEmitter[i], occluder[j], hOccluder[j]));
      lo = glm::min(lo, x);
      hi = glm::max(hi, x);
    }
  Vec2 rlo(std::numeric_limits<double>::infinity()), rhi(-std::numeric_limits<double>::infinity());
  for (const Vec2& p : receiver.outline) {
    rlo = glm::min(rlo, p);
    rhi = glm::max(rhi, p);
  }
  const double t = receiver.tolerance;
  return hi.x < rlo.x - t || hi.y < rlo.y - t || lo.x > rhi.x + t || lo.y > rhi.y + t;
}

// The EV and VE wedges of one (emitter, occluder, receiver) triple that is not culled.
void wedgeEvents(const std::vector<Vec3>& E, const PolygonGeometry& emitter, const std::vector<Vec3>& O,
                 const PolygonGeometry& receiver, ReceiverEvents& events) {
  Wedge wedge;
  wedge.emitterNormal = emitter.frame.n;
  const double tolR = receiver.tolerance, tolE = emitter.tolerance;
  std::vector<double> hE(E.size()), hO(O.size()), hOE(O.size());
  for (size_t i = 0; i < E.size(); ++i) hE[i] = receiver.height(E[i]);
  for (size_t j = 0; j < O.size(); ++j) {
    hO[j] = receiver.height(O[j]);
    hOE[j] = emitter.height(O[j]);
  }
  const double hEmitterTop = *std::max_element(hE.begin(), hE.end());

  // EV: emitter vertex e, occluder edge O[j] O[k]; the wedge is the part of the plane
  // (e, edge) beyond the edge, seen from e; it meets the receiver's plane in the edge's
  // central projection from e. Kept: the part of the edge in front of the emitter's plane and
  // between the receiver's plane and e's height (where that projection exists).
  for (size_t i = 0; i < E.size(); ++i) {
    if (hE[i] <= tolR) continue;
    for (size_t j = 0; j < O.size(); ++j) {
      const size_t k = (j + 1) % O.size();
      const Vec3 normal = glm::cross(O[k] - O[j], E[i] - O[j]);
      if (glm::length(normal) <= tolR * glm::length(O[k] - O[j])) continue;  // e on the edge's line
      double t0 = 0, t1 = 1;
      keepNonNegative(hO[j] + tolR, hO[k] + tolR, t0, t1);
      keepNonNegative(hE[i] * (1 - 1e-6) - hO[j], hE[i] * (1 - 1e-6) - hO[k], t0, t1);
      keepNonNegative(hOE[j] - tolE, hOE[k] - tolE, t0, t1);
      if (!(t1 - t0 > 1e-12)) continue;
      auto at = [&](double t) {
        const Vec3 q = O[j] + t * (O[k] - O[j]);
        return projectFrom(E[i], hE[i], q, std::max(0.0, receiver.height(q)));
      };
      const bool d1 = planeContainsEdgeAt(glm::normalize(normal), E, i);
      wedge.emitterVertex = true;
      wedge.fixed = E[i], wedge.edge0 = O[j], wedge.edge1 = O[k];
      events.add(at(t0), at(t1), EventKind::EmitterVertexOccluderEdge, d1 ? Continuity::C0 : Continuity::C1, &wedge);
    }
  }

  // VE: occluder vertex v, emitter edge E[i] E[k]; the wedge is the plane (v, edge) beyond v,
  // and meets the receiver's plane in the edge's central projection through v. Kept: the
  // part of the emitter edge above v (measured from the receiver).
  for (size_t j = 0; j < O.size(); ++j) {
    if (hO[j] <= tolR || hOE[j] <= tolE) continue;  // a vertex on the receiver casts a point
    for (size_t i = 0; i < E.size(); ++i) {
      const size_t k = (i + 1) % E.size();
      const Vec3 normal = glm::cross(E[k] - E[i], O[j] - E[i]);
      if (glm::length(normal) <= tolE * glm::length(E[k] - E[i])) continue;
      double t0 = 0, t1 = 1;
      const double margin = hO[j] + 1e-6 * hEmitterTop;
      keepNonNegative(hE[i] - margin, hE[k] - margin, t0, t1);
      if (!(t1 - t0 > 1e-12)) continue;
      auto at = [&](double t) {
        const Vec3 p = E[i] + t * (E[k] - E[i]);
        return projectFrom(p, receiver.height(p), O[j], hO[j]);
      };
      const bool d1 = planeContainsEdgeAt(glm::normalize(normal), O, j);
      wedge.emitterVertex = false;
      wedge.fixed = O[j], wedge.edge0 = E[i], wedge.edge1 = E[k];
      events.add(at(t0), at(t1), EventKind::OccluderVertexEmitterEdge, d1 ? Continuity::C0 : Continuity::C1, &wedge);
    }
  }
}

// The bounding tests of findDiscontinuityEvents: true when the occluder cannot shadow the
// receiver from the emitter.
bool culled(const std::vector<Vec3>& E, const PolygonGeometry& emitter, const std::vector<Vec3>& O,
            const PolygonGeometry& receiver, const std::vector<Vec3>& R) {
  const double tolR = receiver.tolerance, tolE = emitter.tolerance;
  std::vector<double> hE, hO, hOE;
  for (const Vec3& e : E) hE.push_back(receiver.height(e));
  for (const Vec3& o : O) {
    hO.push_back(receiver.height(o));
    hOE.push_back(emitter.height(o));
  }
  double receiverFarthest = -std::numeric_limits<double>::infinity();
  for (const Vec3& r : R) receiverFarthest = std::max(receiverFarthest, emitter.height(r));
  const auto [hOLow, hOHigh] = std::minmax_element(hO.begin(), hO.end());
  const auto [hOELow, hOEHigh] = std::minmax_element(hOE.begin(), hOE.end());
  const double hETop = *std::max_element(hE.begin(), hE.end());
  if (hETop <= tolR || receiverFarthest <= tolE) return true;  // the emitter does not light it
  if (*hOEHigh <= tolE || *hOHigh <= tolR) return true;        // behind the emitter / receiver
  // Along a ray from the emitter to the receiver, the height above the receiver falls from
  // the emitter's to 0 and the distance in front of the emitter grows from 0 to the
  // receiver's: an occluder outside either range is never on such a ray.
  if (*hOLow >= hETop - tolR || *hOELow >= receiverFarthest - tolE) return true;
  return shadowMissesReceiver(receiver, E, hE, O, hO, hOE);
}

// D0 on receiver r: every other polygon (emitters too) whose bounding box reaches the receiver's,
// and the flat footprints on it.
void addContacts(const Scene& scene, const std::vector<PolygonGeometry>& geometry, size_t r, ReceiverEvents& events) {
  const PolygonGeometry& receiver = geometry[r];
  for (size_t p = 0; p < geometry.size(); ++p) {
    if (p == r || !geometry[p].valid) continue;
    const double slack = kEventTolerance * (receiver.size + geometry[p].size) + kFlatFootprintGap * geometry[p].size;
    const Bounds& a = receiver.bounds;
    const Bounds& b = geometry[p].bounds;
    if (glm::any(glm::lessThan(a.hi + slack, b.lo)) || glm::any(glm::lessThan(b.hi + slack, a.lo))) continue;
    for (const auto& [x0, x1] : planeContact(receiver, scene.polygons[p].vertices, geometry[p]))
      events.add(x0, x1, EventKind::Contact, Continuity::Cm1);
    double gap = 0.0;
    for (const auto& [x0, x1] : flatFootprint(receiver, scene.polygons[p].vertices, geometry[p], gap))
      events.add(x0, x1, EventKind::Contact, Continuity::Cm1, nullptr, gap);
  }
}

}  // namespace

std::vector<std::vector<EventSegment>> findContacts(const Scene& scene) {
  std::vector<PolygonGeometry> geometry;
  for (const Polygon& p : scene.polygons) geometry.push_back(describe(p));
  std::vector<std::vector<EventSegment>> segments(scene.polygons.size());
  EventCounts counts;
  for (size_t r = 0; r < scene.polygons.size(); ++r) {
    if (!geometry[r].valid) continue;
    ReceiverEvents events(geometry[r], segments[r], counts, nullptr);
    addContacts(scene, geometry, r, events);
  }
  return segments;
}

std::vector<std::vector<EventSegment>> findDiscontinuityEvents(const Scene& scene, EventCounts& counts,
                                                               const CriticalLineTest* criticalLines) {
  const size_t n = scene.polygons.size();
  std::vector<PolygonGeometry> geometry;
  geometry.reserve(n);
  for (const Polygon& p : scene.polygons) geometry.push_back(describe(p));
  std::vector<int> emitters;
  for (size_t p = 0; p < n; ++p)
    if (geometry[p].valid && scene.materials[scene.polygons[p].material].isEmitter()) emitters.push_back(int(p));
  auto isEmitter = [&](size_t p) { return std::find(emitters.begin(), emitters.end(), int(p)) != emitters.end(); };

  std::vector<std::vector<EventSegment>> segments(n);
  for (size_t r = 0; r < n; ++r) {
    const PolygonGeometry& receiver = geometry[r];
    if (!receiver.valid || isEmitter(r)) continue;
    ReceiverEvents events(receiver, segments[r], counts, criticalLines);
    const std::vector<Vec3>& R = scene.polygons[r].vertices;

    addContacts(scene, geometry, r, events);

    // EV and VE: every emitter, every occluder that is neither it nor the receiver.
    for (int e : emitters) {
      const std::vector<Vec3>& E = scene.polygons[e].vertices;
      for (size_t o = 0; o < n; ++o) {
        if (o == r || !geometry[o].valid || isEmitter(o)) continue;
        const std::vector<Vec3>& O = scene.polygons[o].vertices;
        if (culled(E, geometry[e], O, receiver, R)) {
          ++counts.triplesCulled;
          continue;
        }
        ++counts.triplesKept;
        wedgeEvents(E, geometry[e], O, receiver, events);
      }
    }
    events.putCutEndsOnWhatBlocksThem();
  }
  return segments;
}

}  // namespace radview
