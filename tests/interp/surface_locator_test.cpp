// SurfaceLocator against its definition, nearestSurfacePoint's brute force: the same element,
// point and distance, bit for bit, for points on, near and far from meshes of every kind the
// tests have, at the extreme scales and placements, and at ties (vertices and shared edges,
// where several elements are equally near and the lowest index must win).
#include "interp/surface_locator.h"

#include "core/error.h"
#include "tests/extreme_scenes.h"
#include "tests/interp/test_meshes.h"

#include <gtest/gtest.h>

#include <random>

namespace radview {
namespace {

// Every point gets exactly the brute force's answer.
void expectSameAsBruteForce(const RadiosityMesh& mesh, const std::vector<Vec3>& points) {
  const SurfaceLocator locator(mesh);
  for (const Vec3& p : points) {
    const SurfacePoint want = nearestSurfacePoint(mesh, p);
    const SurfacePoint got = locator.nearest(p);
    ASSERT_EQ(got.element, want.element) << "at " << test::str(p) << ": distance " << got.distance << " vs "
                                         << want.distance;
    ASSERT_EQ(got.distance, want.distance) << "at " << test::str(p);
    ASSERT_EQ(got.x, want.x) << "at " << test::str(p) << ": " << test::str(got.x) << " vs " << test::str(want.x);
  }
}

// Every `stride`-th node and edge midpoint (the ties), and `count` points uniformly in the box
// around the mesh widened by `spread` of its diagonal (points on, near and off the surface).
std::vector<Vec3> probePoints(const RadiosityMesh& mesh, double spread, uint32_t seed, size_t stride = 1,
                              int count = 2000) {
  std::mt19937 random(seed);
  const Bounds b = mesh.bounds();
  const Vec3 margin(spread * b.diagonal());
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec3> points;
  for (size_t n = 0; n < mesh.nodes.size(); n += stride) points.push_back(mesh.nodes[n].position);
  for (size_t i = 0; i < mesh.elements.size(); i += stride) {
    const auto& c = mesh.elements[i].corners;
    for (size_t k = 0; k < c.size(); ++k)
      points.push_back(0.5 * (mesh.nodes[c[k]].position + mesh.nodes[c[(k + 1) % c.size()]].position));
  }
  for (int i = 0; i < count; ++i) {
    const Vec3 t(unit(random), unit(random), unit(random));
    points.push_back(b.lo - margin + t * (b.hi - b.lo + 2.0 * margin));
  }
  return points;
}

const test::Field kField = [](const Vec2& p) { return Rgb(1.0 + p.x, 2.0 - p.y, 0.5); };

TEST(SurfaceLocator, JitteredTrianglesAndQuadsInATiltedPlane) {
  for (bool quads : {false, true}) {
    SCOPED_TRACE(quads ? "quads" : "triangles");
    const RadiosityMesh mesh = test::gridMesh(12, quads, 0.3, kField, 7);
    expectSameAsBruteForce(mesh, probePoints(mesh, 0.2, 11));
  }
}

TEST(SurfaceLocator, SliversOfAspect1e6) {
  const RadiosityMesh mesh = test::sliverMesh(10, 1e6, 0.3, kField, 5);
  expectSameAsBruteForce(mesh, probePoints(mesh, 0.05, 3));
}

TEST(SurfaceLocator, ClosedBoxAtExtremeScalesAndPlacements) {
  for (const test::Placement& placement : test::extremePlacements()) {
    SCOPED_TRACE(placement.name);
    const RadiosityMesh mesh = test::extremeBox(placement);
    expectSameAsBruteForce(mesh, probePoints(mesh, 0.1, 17, 23, 300));
  }
}

TEST(SurfaceLocator, PointsFarFromTheMeshFindItsNearestElement) {
  const RadiosityMesh mesh = test::gridMesh(6, true, 0.2, kField, 2);
  expectSameAsBruteForce(mesh, {Vec3(1e30, -1e30, 1e29), Vec3(-1e6, 3.0, 2.0)});
}

TEST(SurfaceLocator, AMeshWithoutElementsIsRefused) {
  RadiosityMesh empty;
  empty.materials.push_back(Material{"grey", Rgb(0.5), Rgb(0.0)});
  EXPECT_THROW(SurfaceLocator{empty}, Error);
}

}  // namespace
}  // namespace radview
