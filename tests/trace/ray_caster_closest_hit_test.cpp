#include "trace/ray_caster.h"

#include <gtest/gtest.h>

namespace radview {
namespace {

// Two unit squares facing +z at z = 0 and z = 1 (polygon 0 and 1), far from the origin so the
// normalised frame matters, and a zero-area polygon in between that must be skipped.
Scene stackedSquares(const Vec3& offset) {
  Scene scene;
  scene.materials = {{"grey", {0.5, 0.5, 0.5}, {0, 0, 0}}};
  auto square = [&](double z) {
    return Polygon{{offset + Vec3(0, 0, z), offset + Vec3(1, 0, z), offset + Vec3(1, 1, z), offset + Vec3(0, 1, z)}, 0};
  };
  scene.polygons = {square(0.0), {{offset, offset, offset}, 0}, square(1.0)};
  return scene;
}

TEST(RayCasterClosestHitTest, FindsTheNearestPolygonItsSideAndThePoint) {
  const Vec3 offset(1e4, -2e4, 3e4);
  const RayCaster caster(stackedSquares(offset));
  EXPECT_EQ(caster.skippedPolygons(), 1u);

  // From above: the top square's front.
  auto hit = caster.closestHit({offset + Vec3(0.25, 0.5, 3.0), {0, 0, -1}});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->polygon, 2u);
  EXPECT_TRUE(hit->front);
  EXPECT_NEAR(hit->distance, 2.0, 1e-5);
  EXPECT_LT(glm::distance(hit->position, offset + Vec3(0.25, 0.5, 1.0)), 1e-6);  // float in a frame of size ~1.7

  // From between them, upwards: the top square's back.
  hit = caster.closestHit({offset + Vec3(0.5, 0.5, 0.5), {0, 0, 1}});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->polygon, 2u);
  EXPECT_FALSE(hit->front);

  // Leaving the bottom square's surface (lifted off it): it does not hit itself.
  hit = caster.closestHit({offset + Vec3(0.5, 0.5, 0.0), glm::normalize(Vec3(0.1, 0, 1)), {0, 0, 1}});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->polygon, 2u);

  // Off to the side: nothing.
  EXPECT_FALSE(caster.closestHit({offset + Vec3(3, 3, 0.5), {0, 0, -1}}));
}

}  // namespace
}  // namespace radview
