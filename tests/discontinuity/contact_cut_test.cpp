// A uniform mesh cut along the blocks' footprints, and rid of what the blocks cover.
#include "discontinuity/contact_cut.h"

#include "geom/polygon.h"
#include "mesh/uniform_mesher.h"
#include "tests/solve/solver_scenes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace radview {
namespace {

// Strictly inside a convex polygon of the floor (either way round), in (x, z).
bool inside(const Vec3& p, const std::vector<Vec3>& footprint) {
  int left = 0, right = 0;
  for (size_t i = 0; i < footprint.size(); ++i) {
    const Vec3& a = footprint[i];
    const Vec3& b = footprint[(i + 1) % footprint.size()];
    const double turn = (b.x - a.x) * (p.z - a.z) - (b.z - a.z) * (p.x - a.x);
    left += turn > 1e-9;
    right += turn < -1e-9;
  }
  return left == int(footprint.size()) || right == int(footprint.size());
}

// The bottom edges of a block's sides (polygons first .. first + 3), in order round it.
std::vector<Vec3> footprintOf(const Scene& scene, size_t first) {
  std::vector<Vec3> footprint;
  for (size_t side = first; side < first + 4; ++side) footprint.push_back(scene.polygons[side].vertices[0]);
  return footprint;
}

TEST(ContactCut, TheFloorIsCutAlongTheFootprintsAndWhatTheBlocksCoverIsLeftOut) {
  const Scene scene = test::cornellBox();
  const RadiosityMesh uniform = meshUniformly(scene, 100.0);
  const RadiosityMesh cut = cutAtContacts(scene, uniform);
  validateMesh(cut, "cut Cornell box");
  // Sides 7-10 and 12-15 stand on the floor; their first vertex is on it.
  const std::vector<Vec3> shortBlock = footprintOf(scene, 7), tallBlock = footprintOf(scene, 12);
  double floorArea = 0.0;
  for (uint32_t e = 0; e < cut.elements.size(); ++e) {
    const std::vector<Vec3> corners = cut.cornerPositions(e);
    EXPECT_TRUE(isConvex(corners)) << "element " << e;
    if (cut.elements[e].surface != 0) continue;
    floorArea += area(corners);
    const Vec3 c = centroid(corners);
    EXPECT_FALSE(inside(c, shortBlock) || inside(c, tallBlock)) << "element " << e << " lies under a block";
  }
  // What is left of the floor is the floor less the footprints, exactly: no element crosses one.
  const double expected = area(scene.polygons[0].vertices) - area(shortBlock) - area(tallBlock);
  EXPECT_NEAR(floorArea, expected, 1e-9 * expected);
  // The ceiling is cut along the outline of the light 0.1 mm under it (a flat footprint), and
  // what the light hides is left out: the ceiling less the light, exactly.
  double ceilingArea = 0.0;
  for (uint32_t e = 0; e < cut.elements.size(); ++e)
    if (cut.elements[e].surface == 2) ceilingArea += area(cut.cornerPositions(e));
  const double ceilingExpected = area(scene.polygons[2].vertices) - area(scene.polygons[1].vertices);
  EXPECT_NEAR(ceilingArea, ceilingExpected, 1e-9 * ceilingExpected);
  // The walls, which nothing stands on, are as the uniform mesh made them.
  size_t backWall = 0, uniformBackWall = 0;
  for (const Element& element : cut.elements) backWall += element.surface == 3;
  for (const Element& element : uniform.elements) uniformBackWall += element.surface == 3;
  EXPECT_EQ(backWall, uniformBackWall);
}

TEST(ContactCut, AnEmittingFloorIsCutToo) {
  // The furnace's floor emits: under the block it would emit into the block, for nothing.
  const Scene scene = test::furnaceWithBlock(Rgb(0.5), Rgb(1.0));
  const RadiosityMesh cut = cutAtContacts(scene, meshUniformly(scene, 0.25));
  double floorArea = 0.0;
  for (uint32_t e = 0; e < cut.elements.size(); ++e)
    if (cut.elements[e].surface == 4) floorArea += area(cut.cornerPositions(e));  // y = 0
  EXPECT_NEAR(floorArea, 1.0 - 0.4 * 0.4, 1e-12);
}

}  // namespace
}  // namespace radview
