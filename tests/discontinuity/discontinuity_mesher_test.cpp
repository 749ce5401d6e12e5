// The discontinuity mesh as a whole: D0 contacts with duplicated nodes, the Cornell box,
// solution files, and robustness on degenerate input.
#include "discontinuity/discontinuity_mesher.h"

#include "discontinuity/discontinuity_segments.h"
#include "geom/constrained_mesh_cgal.h"
#include "geom/polygon.h"
#include "import/load_file.h"
#include "mesh/solution_file.h"
#include "mesh/topology.h"
#include "scene/gltf_document.h"
#include "solve/direct_light.h"

#include "tests/test_print.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <set>
#include <sstream>

namespace radview {
namespace {

using test::str;

using Quad = std::vector<Vec3>;

Material white() { return {"white", {0.5, 0.5, 0.5}, {0, 0, 0}}; }
Material light() { return {"light", {0, 0, 0}, {10, 10, 10}}; }

// The axis-aligned box [x0, x1] x [y0, y1] x [z0, z1] without its bottom, faces outward.
std::vector<Quad> openBox(double x0, double x1, double y0, double y1, double z0, double z1) {
  return {{{x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}},
          {{x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}},
          {{x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1}},
          {{x1, y1, z0}, {x0, y1, z0}, {x0, y1, z1}, {x1, y1, z1}},
          {{x0, y1, z0}, {x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}}};
}

Quad floorQuad(double half) { return {{-half, -half, 0}, {half, -half, 0}, {half, half, 0}, {-half, half, 0}}; }
Quad lightQuad(double half, double z) {
  return {{-half, -half, z}, {-half, half, z}, {half, half, z}, {half, -half, z}};
}

Scene boxOnFloor() {
  Scene scene;
  scene.materials = {white(), light()};
  scene.polygons.push_back({floorQuad(2.0), 0});
  scene.polygons.push_back({lightQuad(0.5, 3.0), 1});
  for (const Quad& q : openBox(-0.5, 0.5, -0.5, 0.5, 0.0, 1.0)) scene.polygons.push_back({q, 0});
  return scene;
}

// The parts of [p, q] covered by the tagged edges of `order` on `surface`, as a fraction.
double coveredFraction(const RadiosityMesh& mesh, Continuity order, int surface, const Vec3& p, const Vec3& q,
                       double tolerance) {
  std::set<std::pair<uint32_t, uint32_t>> onSurface;
  for (const Element& e : mesh.elements)
    if (e.surface == surface)
      for (size_t k = 0; k < e.corners.size(); ++k)
        onSurface.insert(std::minmax(e.corners[k], e.corners[(k + 1) % e.corners.size()]));
  std::vector<std::pair<double, double>> spans;
  const double length = glm::distance(p, q);
  for (const DiscontinuityEdge& d : mesh.discontinuities) {
    if (d.order != order || !onSurface.count(std::minmax(d.a, d.b))) continue;
    const Vec3 a = mesh.nodes[d.a].position, b = mesh.nodes[d.b].position;
    auto param = [&](const Vec3& x) { return glm::dot(x - p, q - p) / (length * length); };
    auto off = [&](const Vec3& x) { return glm::distance(x, p + param(x) * (q - p)); };
    if (off(a) > tolerance || off(b) > tolerance) continue;
    spans.push_back(std::minmax(param(a), param(b)));
  }
  std::sort(spans.begin(), spans.end());
  double covered = 0, reach = 0;
  for (auto [lo, hi] : spans) {
    lo = std::max(lo, reach);
    hi = std::min(hi, 1.0);
    if (hi > lo) covered += hi - lo;
    reach = std::max(reach, hi);
  }
  return covered;
}

TEST(DiscontinuityMesherTest, BoxOnTheFloorGivesCm1EdgesAlongItsFootprintWithDuplicatedNodes) {
  const Scene scene = boxOnFloor();
  DiscontinuityMeshReport report;
  const RadiosityMesh mesh = meshWithDiscontinuities(scene, 0.25, &report);
  validateMesh(mesh, "box on floor");
  const MeshTopology topology(mesh);
  std::cout << report << "\n";
  // Contacts: the floor with 4 sides, the top with 4, each side with the floor, the top and 2
  // sides; only the floor's lie inside their receiver, the others on its boundary.
  EXPECT_EQ(report.contactEvents, 24u);
  EXPECT_EQ(report.segmentsCm1, 4u);
  const Vec3 corners[] = {{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0.5, 0.5, 0}, {-0.5, 0.5, 0}};
  for (int k = 0; k < 4; ++k)
    EXPECT_NEAR(coveredFraction(mesh, Continuity::Cm1, 0, corners[k], corners[(k + 1) % 4], 1e-12), 1.0, 1e-12) << k;
  size_t cm1 = 0;
  for (const DiscontinuityEdge& d : mesh.discontinuities) {
    if (d.order != Continuity::Cm1) continue;
    ++cm1;
    const Vec3 a = mesh.nodes[d.a].position, b = mesh.nodes[d.b].position;
    EXPECT_NEAR(std::max(std::abs(a.x), std::abs(a.y)), 0.5, 1e-12) << str(a);
    EXPECT_NEAR(a.z, 0.0, 0.0);
    // The other side: a floor element with an edge at the same positions and other nodes.
    bool otherSide = false;
    for (const Element& e : mesh.elements) {
      if (e.surface != 0) continue;
      for (size_t k = 0; k < 3; ++k) {
        const uint32_t u = e.corners[k], v = e.corners[(k + 1) % 3];
        if (mesh.nodes[u].position == b && mesh.nodes[v].position == a && u != d.b && v != d.a) otherSide = true;
      }
    }
    EXPECT_TRUE(otherSide) << str(a) << ' ' << str(b);
  }
  EXPECT_EQ(topology.countEdges(Continuity::Cm1), cm1);
  EXPECT_EQ(report.edgesCm1, cm1);
  // Each footprint corner: one node inside, one outside (a closed C-1 loop cuts the fan twice).
  for (const Vec3& c : corners) {
    std::set<uint32_t> nodes;
    for (const Element& e : mesh.elements)
      if (e.surface == 0)
        for (uint32_t n : e.corners)
          if (mesh.nodes[n].position == c) nodes.insert(n);
    EXPECT_EQ(nodes.size(), 2u) << str(c);
  }
}

TEST(DiscontinuityMesherTest, KeepsTheUniformMesherContract) {
  const Scene scene = boxOnFloor();
  const RadiosityMesh mesh = meshWithDiscontinuities(scene, 0.3, nullptr);
  EXPECT_EQ(mesh.materials.size(), scene.materials.size());
  std::vector<double> areaPerSurface(scene.polygons.size(), 0.0);
  for (size_t i = 0; i < mesh.elements.size(); ++i) {
    const Element& e = mesh.elements[i];
    ASSERT_GE(e.surface, 0);
    EXPECT_EQ(e.material, scene.polygons[e.surface].material);
    const Vec3 n = unitNormal(scene.polygons[e.surface].vertices);
    EXPECT_GT(glm::dot(mesh.elementNormal(i), n), 0.999999) << i;  // counter-clockwise about it
    const auto p = mesh.cornerPositions(i);
    areaPerSurface[e.surface] += 0.5 * glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
    for (size_t k = 0; k < 3; ++k) {
      EXPECT_LE(glm::distance(p[k], p[(k + 1) % 3]), 0.3 * (1 + 1e-9));
      EXPECT_EQ(mesh.nodes[e.corners[k]].B, Rgb(0.0));
    }
  }
  EXPECT_NEAR(areaPerSurface[0], 16.0, 1e-9);
  EXPECT_NEAR(areaPerSurface[1], 1.0, 1e-12);
  EXPECT_NEAR(areaPerSurface[2], 1.0, 1e-12);
}

// The Cornell box as bundled, at radview's default element size.
TEST(DiscontinuityMesherTest, CornellBoxHasFootprintsAsCm1AndRoundTripsThroughASolutionFile) {
  const LoadedFile file = loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/cornell_box.gltf");
  const Scene& scene = file.scene;
  const double size = defaultElementSize(scene);
  DiscontinuityMeshReport report;
  const RadiosityMesh mesh = meshWithDiscontinuities(scene, size, &report);
  std::cout << "element size " << size << "\n" << report << "\n";
  validateMesh(mesh, "cornell box");
  const MeshTopology topology(mesh);
  EXPECT_EQ(topology.countEdges(Continuity::Cm1), report.edgesCm1);
  EXPECT_EQ(topology.countEdges(Continuity::C0), report.edgesC0);
  EXPECT_GT(report.eventsInserted, 0u);
  EXPECT_EQ(report.segmentsCm1, 12u);  // four footprint edges per block, and the light's outline on the ceiling
  EXPECT_EQ(report.segmentsDropped, 0u);
  EXPECT_EQ(report.refinementCapped, 0u);

  // The floor: the polygon with every vertex at y = 0. Block sides: two vertices on it, inside.
  int floor = -1;
  for (size_t p = 0; p < scene.polygons.size(); ++p) {
    bool flat = true;
    for (const Vec3& v : scene.polygons[p].vertices) flat &= v.y == 0.0;
    if (flat) floor = int(p);
  }
  ASSERT_GE(floor, 0);
  int footprintEdges = 0;
  for (const Polygon& polygon : scene.polygons) {
    const auto& v = polygon.vertices;
    for (size_t k = 0; k < v.size(); ++k) {
      const Vec3 a = v[k], b = v[(k + 1) % v.size()];
      const bool inside = a.x > 0.01 && a.x < 0.54 && b.x > 0.01 && b.x < 0.54 && a.z > 0.01 && a.z < 0.55;
      if (a.y != 0.0 || b.y != 0.0 || !inside) continue;
      ++footprintEdges;
      EXPECT_NEAR(coveredFraction(mesh, Continuity::Cm1, floor, a, b, 1e-7), 1.0, 1e-9) << str(a) << ' ' << str(b);
    }
  }
  EXPECT_EQ(footprintEdges, 8);

  const std::string path = ::testing::TempDir() + "discontinuity_cornell.glb";
  writeSolution(mesh, path);
  const RadiosityMesh back = readSolution(GltfDocument(path));
  EXPECT_EQ(back.elements.size(), mesh.elements.size());
  EXPECT_EQ(back.discontinuities.size(), mesh.discontinuities.size());
  const MeshTopology backTopology(back);
  EXPECT_EQ(backTopology.countEdges(Continuity::Cm1), report.edgesCm1);
  EXPECT_EQ(backTopology.countEdges(Continuity::C0), report.edgesC0);
  if (const char* dump = std::getenv("RADVIEW_DISCONTINUITY_DUMP")) {
    RadiosityMesh lit = mesh;
    solveDirectIllumination(scene, lit);
    writeSolution(lit, dump);
  }
}

void expectValid(const Scene& scene, double size, const char* what, DiscontinuityMeshReport* report = nullptr,
                 size_t allowedCapped = 0) {
  DiscontinuityMeshReport local;
  DiscontinuityMeshReport& r = report ? *report : local;
  RadiosityMesh mesh;
  ASSERT_NO_THROW(mesh = meshWithDiscontinuities(scene, size, &r)) << what;
  ASSERT_NO_THROW(validateMesh(mesh, what));
  ASSERT_NO_THROW(MeshTopology{mesh}) << what;
  EXPECT_LE(r.refinementCapped, allowedCapped) << what;
  for (size_t i = 0; i < mesh.elements.size(); ++i) {
    const auto p = mesh.cornerPositions(i);
    EXPECT_GT(glm::length(glm::cross(p[1] - p[0], p[2] - p[0])), 0.0) << what << " element " << i;
  }
}

TEST(DiscontinuityMesherTest, CoincidentOccludersGiveTheSameLinesOnce) {
  Scene scene;
  scene.materials = {white(), light()};
  scene.polygons.push_back({floorQuad(2.0), 0});
  scene.polygons.push_back({lightQuad(0.5, 2.0), 1});
  scene.polygons.push_back({floorQuad(0.5), 0});
  for (Vec3& v : scene.polygons.back().vertices) v.z = 1.0;
  scene.polygons.push_back(scene.polygons.back());  // the same occluder twice
  scene.polygons.push_back(scene.polygons.back());
  for (Vec3& v : scene.polygons.back().vertices) v.x += 1e-13;  // and once off by rounding
  DiscontinuityMeshReport report;
  expectValid(scene, 0.25, "coincident occluders", &report);
  EXPECT_EQ(report.segmentsC0, 8u) << report;
}

TEST(DiscontinuityMesherTest, EventsThroughPolygonVerticesAndAlongItsEdges) {
  // Floor exactly the penumbra square [-1.5, 1.5]^2: the penumbra lines lie on its edges and
  // the umbra lines end on them.
  Scene scene;
  scene.materials = {white(), light()};
  scene.polygons.push_back({floorQuad(1.5), 0});
  scene.polygons.push_back({lightQuad(0.5, 2.0), 1});
  scene.polygons.push_back({floorQuad(0.5), 0});
  for (Vec3& v : scene.polygons.back().vertices) v.z = 1.0;
  DiscontinuityMeshReport report;
  expectValid(scene, 0.2, "events on the boundary", &report);
  EXPECT_EQ(report.segmentsC0, 4u) << report;
}

TEST(DiscontinuityMesherTest, TinyAndSliverPolygonsMeshWithoutTrouble) {
  Scene scene = boxOnFloor();
  scene.polygons.push_back({{{0.1, 0.1, 2}, {0.1 + 1e-9, 0.1, 2}, {0.1, 0.1 + 1e-9, 2}}, 0});
  scene.polygons.push_back({{{-1, 1, 1.5}, {1, 1, 1.5}, {1, 1 + 1e-6, 1.5}}, 0});
  scene.polygons.push_back({{{1.2, 1.2, 0.5}, {1.2 + 1e-5, 1.2, 0.5}, {1.2, 1.2 + 1e-5, 0.5}}, 0});
  scene.polygons.push_back({{{0, 0, 0}, {1e-300, 0, 0}, {0, 1e-300, 0}}, 0});  // zero area
  // The 2 x 1e-6 sliver cannot be refined to well-shaped triangles of size 0.25 (that takes
  // millions): its refinement stops at the vertex cap, the one polygon allowed to.
  DiscontinuityMeshReport report;
  expectValid(scene, 0.25, "tiny polygons", &report, 1);
  EXPECT_EQ(report.segmentsCm1, 4u) << report;
}

TEST(DiscontinuityMesherTest, ConcaveReceiverWithAShadowAcrossItsNotch) {
  Scene scene;
  scene.materials = {white(), light()};
  scene.polygons.push_back({{{-2, -2, 0}, {2, -2, 0}, {2, 0, 0}, {0, 0, 0}, {0, 2, 0}, {-2, 2, 0}}, 0});
  scene.polygons.push_back({lightQuad(0.5, 2.0), 1});
  scene.polygons.push_back({{{-0.4, -0.5, 1}, {0.6, -0.3, 1}, {0.5, 0.6, 1}, {-0.6, 0.4, 1}}, 0});
  DiscontinuityMeshReport report;
  expectValid(scene, 0.25, "concave receiver", &report);
  EXPECT_GT(report.segmentsC1, 0u);
}

TEST(DiscontinuityMesherTest, ArrangementMergesOverlapsSnapsAndSplits) {
  const std::vector<Vec2> outline = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  std::vector<EventSegment> segments = {
      {{1, 1}, {3, 1}, Continuity::C1, EventKind::EmitterVertexOccluderEdge},
      {{2, 1}, {3.5, 1}, Continuity::C0, EventKind::OccluderVertexEmitterEdge},  // overlaps: C0 wins
      {{1, 1 + 1e-13}, {3, 1 - 1e-13}, Continuity::C1, EventKind::Contact},      // near-duplicate
      {{2, 0}, {2, 3}, Continuity::C1, EventKind::EmitterVertexOccluderEdge},    // crosses, from the boundary
      {{0, 4}, {4, 0}, Continuity::C1, EventKind::EmitterVertexOccluderEdge},    // corner to corner
      {{3, 2}, {3, 1 + 1e-12}, Continuity::Cm1, EventKind::Contact}};            // T onto the first
  const SegmentArrangement arrangement = arrangeSegments(outline, segments, 1e-7 * std::sqrt(32.0));
  const auto& points = arrangement.graph.points;
  for (size_t i = 0; i < points.size(); ++i)
    for (size_t j = i + 1; j < points.size(); ++j)
      EXPECT_GT(glm::distance(points[i], points[j]), 1e-6) << i << ' ' << j;
  EXPECT_EQ(arrangement.mergedSegments[0], 1u);
  EXPECT_EQ(arrangement.mergedSegments[1], 1u);      // [2, 3.5] on y = 1
  EXPECT_EQ(arrangement.mergedSegments[2], 3u);      // [1, 2] on y = 1, x = 2, the diagonal
  EXPECT_EQ(arrangement.graph.boundary.size(), 5u);  // the square plus (2, 0)
  const ConstrainedMesh mesh = constrainedDelaunayMesh(arrangement.graph, 0.5, 100000);
  EXPECT_TRUE(mesh.refinementComplete);
  double total = 0;
  for (const auto& t : mesh.triangles) {
    const Vec2 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    const double twice = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    EXPECT_GT(twice, 1e-4);
    total += 0.5 * twice;
  }
  EXPECT_NEAR(total, 16.0, 1e-9);
  for (size_t s = 0; s < arrangement.graph.segments.size(); ++s) {
    const auto& edges = mesh.segmentEdges[s];
    ASSERT_FALSE(edges.empty()) << s;
    EXPECT_EQ(mesh.inputPoint[edges.front()[0]], arrangement.graph.segments[s][0]);
    EXPECT_EQ(mesh.inputPoint[edges.back()[1]], arrangement.graph.segments[s][1]);
  }
}

// A weaker segment ending within the snapping distance of a stronger one (a wedge cut where
// an occluder's footprint blocks its critical line) ends exactly on it: the C-1 line is split
// there but stays straight, and the wedge keeps its own line.
TEST(DiscontinuityMesherTest, AnEndNearAStrongerSegmentLandsOnItsLine) {
  const std::vector<Vec2> outline = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  const double tolerance = 1e-4;
  const Vec2 footprintA{1, 1}, footprintB{3, 1.5};  // not along an axis: rounding shows
  const Vec2 wedgeFar{2.5, 3};
  const Vec2 onFootprint = footprintA + 0.6 * (footprintB - footprintA);
  const Vec2 wedgeEnd = onFootprint + 0.4 * tolerance * glm::normalize(onFootprint - wedgeFar);  // overshoots
  const std::vector<EventSegment> segments = {
      {footprintA, footprintB, Continuity::Cm1, EventKind::Contact},
      {wedgeFar, wedgeEnd, Continuity::C1, EventKind::OccluderVertexEmitterEdge}};
  const SegmentArrangement arrangement = arrangeSegments(outline, segments, tolerance);
  const auto& points = arrangement.graph.points;
  const Vec2 along = glm::normalize(footprintB - footprintA), wedge = glm::normalize(wedgeEnd - wedgeFar);
  auto offLine = [](const Vec2& p, const Vec2& origin, const Vec2& direction) {
    const Vec2 d = p - origin;
    return std::abs(d.x * direction.y - d.y * direction.x);
  };
  size_t cm1Pieces = 0;
  for (size_t s = 0; s < arrangement.graph.segments.size(); ++s)
    for (int end : arrangement.graph.segments[s]) {
      const Vec2 p = points[end];
      if (arrangement.order[s] == Continuity::Cm1) {
        EXPECT_LT(offLine(p, footprintA, along), 1e-14) << "the C-1 line stays straight";
        cm1Pieces += end == arrangement.graph.segments[s][0];
      } else {
        EXPECT_LT(offLine(p, wedgeFar, wedge), 1e-14) << "the wedge stays on its line";
      }
    }
  EXPECT_EQ(cm1Pieces, 2u);  // split at the wedge's end
}

TEST(DiscontinuityMesherTest, RandomOccludersNeverBreakTheMesh) {
  std::mt19937 random(12345);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 12; ++trial) {
    Scene scene;
    scene.materials = {white(), light()};
    scene.polygons.push_back({floorQuad(2.0), 0});
    scene.polygons.push_back({lightQuad(0.4 + 0.4 * unit(random), 2.5), 1});
    for (int k = 0; k < 3; ++k) {
      const Vec3 c(2 * unit(random) - 1, 2 * unit(random) - 1, 0.3 + 1.8 * unit(random));
      const double angle = 6.283 * unit(random), tilt = 0.5 * unit(random) - 0.25, r = 0.2 + 0.5 * unit(random);
      Quad q;
      for (int i = 0; i < 4; ++i) {
        const double a = angle + i * 1.5708;
        q.push_back(c + Vec3(r * std::cos(a), r * std::sin(a), tilt * r * std::cos(a)));
      }
      scene.polygons.push_back({q, 0});
    }
    expectValid(scene, 0.2, ("random trial " + std::to_string(trial)).c_str());
  }
}

}  // namespace
}  // namespace radview
