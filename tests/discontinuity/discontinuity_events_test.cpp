// Discontinuity events against their closed forms: parallel squares (D1, similar triangles),
// a rotated occluder (D2), culling, and the segment clipper.
#include "discontinuity/discontinuity_events.h"

#include "discontinuity/critical_lines.h"
#include "discontinuity/discontinuity_mesher.h"
#include "geom/polygon.h"
#include "import/load_file.h"
#include "mesh/topology.h"

#include "tests/test_print.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

namespace radview {
namespace {

using test::str;

// Square of side `side` centred on the z axis at height z, turned by `angle` about z, facing
// up (+z) or down.
std::vector<Vec3> square(double side, double z, bool facingUp, double angle = 0.0) {
  std::vector<Vec3> v;
  for (int k = 0; k < 4; ++k) {
    const double a = angle + (facingUp ? 1 : -1) * (0.25 + 0.5 * k) * 3.14159265358979323846;
    v.push_back({side / std::sqrt(2.0) * std::cos(a), side / std::sqrt(2.0) * std::sin(a), z});
  }
  return v;
}

// Polygons: 0 the floor (side 4, z = 0), 1 the emitter (side a, height h, facing down),
// 2 the occluder (side b, height o, facing up, turned by `angle`).
Scene squaresScene(double a, double h, double b, double o, double angle = 0.0) {
  Scene scene;
  scene.materials = {{"white", {0.5, 0.5, 0.5}, {0, 0, 0}}, {"light", {0, 0, 0}, {10, 10, 10}}};
  scene.polygons.push_back({square(4.0, 0.0, true), 0});
  scene.polygons.push_back({square(a, h, false), 1});
  scene.polygons.push_back({square(b, o, true, angle), 0});
  return scene;
}

// A small square in the umbra of a larger one (the emitter's light reaches no point of it)
// casts wedges on the floor whose critical lines all pass through the larger square: with the
// critical-line test they are left out, and the floor has exactly the events of the larger
// square alone; without it they are there.
TEST(DiscontinuityEventsTest, WedgesHiddenByAnotherOccluderAreLeftOut) {
  Scene withSmall = squaresScene(1.0, 3.0, 2.0, 2.0);  // the emitter at 3, a blocker of side 2 at 2
  const Scene blockerOnly = withSmall;
  withSmall.polygons.push_back({square(0.4, 1.0, true, 0.3), 0});  // the small square at 1, turned
  const CriticalLinesByRays lines(withSmall);
  EventCounts filtered, unfiltered, alone;
  const auto hidden = findDiscontinuityEvents(withSmall, filtered, &lines);
  const auto all = findDiscontinuityEvents(withSmall, unfiltered);
  const auto reference = findDiscontinuityEvents(blockerOnly, alone);
  EXPECT_GT(all[0].size(), reference[0].size());
  ASSERT_EQ(hidden[0].size(), reference[0].size());
  for (size_t i = 0; i < hidden[0].size(); ++i) {
    EXPECT_EQ(hidden[0][i].a, reference[0][i].a);
    EXPECT_EQ(hidden[0][i].b, reference[0][i].b);
  }
  EXPECT_EQ(filtered.hiddenParts, all[0].size() - reference[0].size());
  EXPECT_GT(filtered.wedgesHidden, 0u);
  // The blocker's own wedges are clear: the test leaves the scene without the small square as
  // it is.
  EventCounts blockerFiltered;
  const CriticalLinesByRays blockerLines(blockerOnly);
  EXPECT_EQ(findDiscontinuityEvents(blockerOnly, blockerFiltered, &blockerLines)[0].size(), reference[0].size());
  EXPECT_EQ(blockerFiltered.hiddenParts, 0u);
}

// A plate at height 2 over x > 0.1 hides part of the emitter from the small square's wedges:
// the critical line from a floor point through a vertex q of the small square (height 1) to a
// point s of the emitter (height 3) crosses height 2 at (q + s) / 2, under the plate where
// q.x + s.x > 0.2. The VE wedges of the emitter edges along x are blocked in part: cut where
// s.x = 0.2 - q.x, on the floor at x = 1.5 q.x - 0.5 s.x = 2 q.x - 0.1 (similar triangles),
// the clear part on the side of larger x.
TEST(DiscontinuityEventsTest, WedgesHiddenInPartAreCutWhereTheirCriticalLineIsBlocked) {
  Scene scene = squaresScene(1.0, 3.0, 0.4, 1.0, 0.3);
  scene.polygons.push_back({{{0.1, -2.0, 2.0}, {2.0, -2.0, 2.0}, {2.0, 2.0, 2.0}, {0.1, 2.0, 2.0}}, 0});
  const CriticalLinesByRays lines(scene);
  EventCounts counts;
  const std::vector<EventSegment> floor = findDiscontinuityEvents(scene, counts, &lines)[0];
  EXPECT_GE(counts.partsCut, 8u);
  const PlaneFrame frame = planeFrame(scene.polygons[0].vertices);
  auto world = [&](const Vec2& p) { return frame.origin + p.x * frame.u + p.y * frame.v; };
  // The ray test lifts each ray's ends off their surfaces by RayCaster::kLift of the scene's
  // size (6e-5 here), which moves where the plate's edge starts to block by about as much.
  const double tolerance = 2.0 * RayCaster::kLift * scene.bounds().diagonal();
  for (const Vec3& q : scene.polygons[2].vertices)
    for (const double sy : {-0.5, 0.5}) {
      const Vec3 cut(2.0 * q.x - 0.1, 1.5 * q.y - 0.5 * sy, 0.0);
      int ending = 0;
      for (const EventSegment& segment : floor) {
        if (segment.kind != EventKind::OccluderVertexEmitterEdge) continue;
        for (const auto& [end, other] : {std::pair{segment.a, segment.b}, std::pair{segment.b, segment.a}}) {
          if (glm::distance(world(end), cut) > tolerance) continue;
          ++ending;
          EXPECT_GT(world(other).x, cut.x) << "the clear part lies at larger x, " << str(cut);
        }
      }
      EXPECT_EQ(ending, 1) << "one wedge piece ends at the cut " << str(cut);
    }
}

// In the Cornell box the short block hides part of the light from wedges of the tall one (and
// the reverse) where they run under it: those pieces are cut where their critical line enters
// the block, on its footprint. Each cut end is put exactly on the footprint's line, where its
// own line meets it; none is left near a footprint but off it, where the footprint would bend
// when the arrangement splits it there.
TEST(DiscontinuityEventsTest, CutEndsLandExactlyOnTheFootprintThatHidesThem) {
  const Scene scene = loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/cornell_box.gltf").scene;
  const CriticalLinesByRays lines(scene);
  EventCounts counts;
  const auto events = findDiscontinuityEvents(scene, counts, &lines);
  EXPECT_GT(counts.partsCut, 0u);
  const double size = scene.bounds().diagonal();
  size_t onFootprint = 0;
  for (const std::vector<EventSegment>& receiver : events)
    for (const EventSegment& wedge : receiver) {
      if (wedge.kind == EventKind::Contact) continue;
      for (const Vec2& end : {wedge.a, wedge.b})
        for (const EventSegment& footprint : receiver) {
          if (footprint.order != Continuity::Cm1) continue;
          const double d = distanceToSegment(end, footprint.a, footprint.b);
          if (d > 1e-4 * size) continue;
          EXPECT_LT(d, 1e-14 * size) << "a wedge end " << d << " off a footprint";
          const bool atCorner = std::min(glm::distance(end, footprint.a), glm::distance(end, footprint.b)) < 1e-9;
          onFootprint += !atCorner;
        }
    }
  EXPECT_GT(onFootprint, 0u) << "some cut ends lie inside a footprint's edge";
}

// square() puts corners on the diagonals: side s gives corners at (+-s/2, +-s/2).
TEST(DiscontinuityEventsTest, SquareHelperMakesAxisAlignedSquares) {
  for (const Vec3& p : square(1.0, 2.0, false)) {
    EXPECT_NEAR(std::abs(p.x), 0.5, 1e-15);
    EXPECT_NEAR(std::abs(p.y), 0.5, 1e-15);
  }
}

// Parallel squares: the umbra boundary |x| or |y| = u and the penumbra boundary = w, with
// (similar triangles, emitter half-side A = a/2 at h, occluder half-side B = b/2 at o)
//   u = A + (B - A) h / (h - o),   w = -A + (B + A) h / (h - o),
// every line spanning [-w, w]: the umbra square's sides extended to the penumbra square are
// EV events too (an emitter corner goes behind an occluder edge). All are D1: each occluder
// edge is parallel to an emitter edge.
struct ParallelSquares {
  double a = 1.0, h = 2.0, b = 1.0, o = 1.0;
  double u() const { return a / 2 + (b / 2 - a / 2) * h / (h - o); }
  double w() const { return -a / 2 + (b / 2 + a / 2) * h / (h - o); }
};

// True when p lies on one of the lines x = +-c or y = +-c for c in `levels`, within the square
// [-w, w]^2, to `tolerance`; `line` gets which (axis * 8 + level index * 2 + sign).
bool onGridLine(const Vec3& p, const std::vector<double>& levels, double w, double tolerance, int* line) {
  for (int axis = 0; axis < 2; ++axis)
    for (size_t l = 0; l < levels.size(); ++l)
      for (int sign = 0; sign < 2; ++sign) {
        const double c = sign ? -levels[l] : levels[l];
        if (std::abs(p[axis] - c) <= tolerance && std::abs(p[1 - axis]) <= w + tolerance) {
          *line = axis * 8 + int(l) * 2 + sign;
          return true;
        }
      }
  return false;
}

void expectParallelSquaresMesh(const ParallelSquares& s, double elementSize) {
  const Scene scene = squaresScene(s.a, s.h, s.b, s.o);
  DiscontinuityMeshReport report;
  const RadiosityMesh mesh = meshWithDiscontinuities(scene, elementSize, &report);
  validateMesh(mesh, "parallel squares");
  const MeshTopology topology(mesh);
  const double tolerance = 1e-9 * 4.0;  // relative to the floor's size
  const std::vector<double> levels = {s.u(), s.w()};
  // Per grid line, the covered intervals along it.
  std::vector<std::vector<std::pair<double, double>>> covered(16);
  for (const DiscontinuityEdge& d : mesh.discontinuities) {
    ASSERT_EQ(d.order, Continuity::C0) << "only D1 events in this scene";
    const Vec3 p = mesh.nodes[d.a].position, q = mesh.nodes[d.b].position;
    EXPECT_NEAR(p.z, 0.0, 1e-15);
    int lineP = -1, lineQ = -1;
    ASSERT_TRUE(onGridLine(p, levels, s.w(), tolerance, &lineP)) << str(p);
    ASSERT_TRUE(onGridLine(q, levels, s.w(), tolerance, &lineQ)) << str(q);
    // Corners lie on two lines; the edge's line is the one both ends share.
    const int axis = std::abs(p.x - q.x) < tolerance ? 0 : 1;
    const double c = p[axis];
    ASSERT_NEAR(q[axis], c, tolerance) << str(p) << ' ' << str(q);
    int line = -1;
    for (size_t l = 0; l < levels.size(); ++l)
      for (int sign = 0; sign < 2; ++sign)
        if (std::abs(c - (sign ? -levels[l] : levels[l])) <= tolerance) line = axis * 8 + int(l) * 2 + sign;
    ASSERT_GE(line, 0) << str(p) << ' ' << str(q);
    covered[line].push_back(std::minmax(p[1 - axis], q[1 - axis]));
  }
  for (int axis = 0; axis < 2; ++axis)
    for (int l = 0; l < 2; ++l)
      for (int sign = 0; sign < 2; ++sign) {
        auto spans = covered[axis * 8 + l * 2 + sign];
        std::sort(spans.begin(), spans.end());
        double reach = -s.w();
        for (const auto& [lo, hi] : spans) {
          EXPECT_LE(lo, reach + tolerance) << "gap on line " << axis << l << sign << " at " << reach;
          reach = std::max(reach, hi);
        }
        EXPECT_NEAR(reach, s.w(), tolerance) << "line " << axis << l << sign;
      }
  EXPECT_EQ(report.segmentsCm1, 0u);
  EXPECT_EQ(report.segmentsC1, 0u);
  EXPECT_EQ(report.segmentsC0, 8u) << report;  // the 8 lines, each merged into one segment
  EXPECT_EQ(topology.countEdges(Continuity::C0), mesh.discontinuities.size());
  std::cout << report << "\n";
}

TEST(DiscontinuityEventsTest, ParallelSquaresUmbraAndPenumbraLinesMatchSimilarTriangles) {
  ParallelSquares s;  // u = 0.5, w = 1.5
  EXPECT_DOUBLE_EQ(s.u(), 0.5);
  EXPECT_DOUBLE_EQ(s.w(), 1.5);
  expectParallelSquaresMesh(s, 0.25);
}

TEST(DiscontinuityEventsTest, ParallelSquaresWithIrrationalRatios) {
  ParallelSquares s;
  s.a = 0.7;
  s.h = 2.3;
  s.b = 0.9;
  s.o = 0.8;  // u = 0.35 + 0.1 * 2.3 / 1.5, w = -0.35 + 0.8 * 2.3 / 1.5
  expectParallelSquaresMesh(s, 0.3);
}

TEST(DiscontinuityEventsTest, RotatedOccluderGivesUntaggedD2WedgesAtTheirCentralProjections) {
  const double h = 2.0, o = 1.0;
  const Scene scene = squaresScene(1.0, h, 1.0, o, 0.5236);
  EventCounts counts;
  const auto events = findDiscontinuityEvents(scene, counts);
  const std::vector<Vec3>& E = scene.polygons[1].vertices;
  const std::vector<Vec3>& O = scene.polygons[2].vertices;
  auto onRing = [](const Vec3& p, const std::vector<Vec3>& ring) {
    for (size_t i = 0; i < ring.size(); ++i) {
      const Vec3 a = ring[i], b = ring[(i + 1) % ring.size()];
      const double t = glm::dot(p - a, b - a) / glm::dot(b - a, b - a);
      if (t >= -1e-12 && t <= 1 + 1e-12 && glm::distance(p, a + t * (b - a)) < 1e-12) return true;
    }
    return false;
  };
  const PlaneFrame floor = planeFrame(scene.polygons[0].vertices);
  size_t ev = 0, ve = 0;
  for (const EventSegment& s : events[0]) {
    EXPECT_EQ(s.order, Continuity::C1);
    for (const Vec2& x2 : {s.a, s.b}) {
      const Vec3 x = floor.origin + x2.x * floor.u + x2.y * floor.v;
      if (s.kind == EventKind::EmitterVertexOccluderEdge) {
        // x = e + h / (h - o) (q - e): q = (x + e) / 2 on an occluder edge, for some e.
        bool found = false;
        for (const Vec3& e : E) found |= onRing(e + (h - o) / h * (x - e), O);
        EXPECT_TRUE(found) << str(x);
        ++ev;
      } else {
        // x = p + k (v - p), k = h / (h - o): p = (x - k v) / (1 - k) on an emitter edge.
        const double k = h / (h - o);
        bool found = false;
        for (const Vec3& v : O) found |= onRing((x - k * v) / (1 - k), E);
        EXPECT_TRUE(found) << str(x);
        ++ve;
      }
    }
  }
  EXPECT_GT(ev, 0u);
  EXPECT_GT(ve, 0u);
  DiscontinuityMeshReport report;
  const RadiosityMesh mesh = meshWithDiscontinuities(scene, 0.25, &report);
  validateMesh(mesh, "rotated occluder");
  MeshTopology topology(mesh);
  EXPECT_TRUE(mesh.discontinuities.empty());
  EXPECT_GT(report.segmentsC1, 8u) << report;
  EXPECT_EQ(report.segmentsC0 + report.segmentsCm1, 0u);
  // Inserted: every D2 segment's midpoint lies on an element edge of the floor.
  for (const EventSegment& s : events[0]) {
    const Vec2 m2 = 0.5 * (s.a + s.b);
    const Vec3 m = floor.origin + m2.x * floor.u + m2.y * floor.v;
    bool onEdge = false;
    for (const Element& e : mesh.elements) {
      if (e.surface != 0 || onEdge) continue;
      for (size_t k = 0; k < 3 && !onEdge; ++k) {
        const Vec3 a = mesh.nodes[e.corners[k]].position, b = mesh.nodes[e.corners[(k + 1) % 3]].position;
        const double t = glm::dot(m - a, b - a) / glm::dot(b - a, b - a);
        onEdge = t >= 0 && t <= 1 && glm::distance(m, a + t * (b - a)) < 1e-9;
      }
    }
    EXPECT_TRUE(onEdge) << str(m);
  }
  std::cout << report << "\n";
}

TEST(DiscontinuityEventsTest, OccludersAboveTheEmitterOrBelowTheReceiverAreCulled) {
  Scene scene = squaresScene(1.0, 2.0, 1.0, 3.0);                                   // occluder above the light
  scene.polygons.push_back({square(1.0, -1.0, false), 0});                          // and one under the floor
  scene.polygons.push_back({{{9, 9, 1}, {10, 9, 1}, {10, 10, 1}, {9, 10, 1}}, 0});  // off to the side
  DiscontinuityMeshReport report;
  const RadiosityMesh mesh = meshWithDiscontinuities(scene, 0.5, &report);
  validateMesh(mesh, "culling");
  EXPECT_EQ(report.eventsFound, 0u) << report;
  EXPECT_EQ(report.segmentsInserted, 0u);
  EXPECT_TRUE(mesh.discontinuities.empty());
  // Receivers floor, above, below, side (4) x occluders among the other 3: 12 triples.
  EXPECT_EQ(report.occludersSkipped, 12u) << report;
  EXPECT_EQ(report.occludersKept, 0u);
  std::ostringstream os;
  os << report;
  EXPECT_NE(os.str().find("12 (emitter, occluder, receiver) triples culled"), std::string::npos) << os.str();
}

TEST(DiscontinuityEventsTest, APolygonLyingAHairInFrontOfAnotherLeavesItsOutlineAsAContact) {
  // The floor (side 4) with squares lying flat above it: one at 1e-3 of its side, one at 2e-2
  // (more than kFlatFootprintGap of its size, an ordinary occluder), one underneath the floor.
  Scene scene;
  scene.materials = {{"white", {0.5, 0.5, 0.5}, {0, 0, 0}}};
  scene.polygons.push_back({square(4.0, 0.0, true), 0});
  scene.polygons.push_back({square(1.0, 1e-3, false), 0});
  Scene far = scene, below = scene;
  far.polygons[1] = {square(1.0, 2e-2, false), 0};
  below.polygons[1] = {square(1.0, -1e-3, true), 0};
  const std::vector<std::vector<EventSegment>> contacts = findContacts(scene);
  ASSERT_EQ(contacts[0].size(), 4u) << "the square's four edges, on the floor";
  for (const EventSegment& edge : contacts[0]) {
    EXPECT_EQ(edge.order, Continuity::Cm1);
    EXPECT_NEAR(edge.gap, 1e-3, 1e-15);
    EXPECT_NEAR(glm::distance(edge.a, edge.b), 1.0, 1e-12);
    // Each end is a corner of the square, in the floor's own frame.
    const PlaneFrame frame = planeFrame(scene.polygons[0].vertices);
    for (const Vec2& end : {edge.a, edge.b}) {
      double nearest = 1e9;
      for (const Vec3& v : scene.polygons[1].vertices)
        nearest = std::min(nearest, glm::distance(end, frame.project(v)));
      EXPECT_LT(nearest, 1e-12);
    }
  }
  EXPECT_TRUE(contacts[1].empty()) << "the floor's outline, dropped onto the square, lies outside it";
  EXPECT_TRUE(findContacts(far)[0].empty());
  EXPECT_TRUE(findContacts(below)[0].empty());
  // Touching contacts keep a gap of 0.
  Scene standing = scene;
  standing.polygons[1] = {{{-0.5, 0, 0}, {0.5, 0, 0}, {0.5, 0, 1}, {-0.5, 0, 1}}, 0};
  const std::vector<EventSegment> foot = findContacts(standing)[0];
  ASSERT_EQ(foot.size(), 1u);
  EXPECT_EQ(foot[0].gap, 0.0);
}

}  // namespace
}  // namespace radview
