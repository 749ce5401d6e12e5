#include "gather/emitter_sampler.h"

#include "gather/hemisphere_sampling.h"
#include "mesh/uniform_mesher.h"
#include "trace/patch_sampler.h"

#include "tests/test_print.h"

#include <gtest/gtest.h>

namespace radview {
namespace {

TEST(EmitterSamplerTest, PicksEmittersByPowerWithTheMatchingDensity) {
  // Two emitters: a 1 x 1 square of E 1 and a 2 x 1 rectangle of E 3 (power 1 : 6), and a
  // non-emitting floor, which is never picked.
  Scene scene;
  scene.materials = {
      {"floor", {0.5, 0.5, 0.5}, {0, 0, 0}}, {"dim", {0, 0, 0}, {1, 1, 1}}, {"bright", {0, 0, 0}, {3, 3, 3}}};
  scene.polygons.push_back({{{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}}, 0});
  scene.polygons.push_back({{{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}}, 1});
  scene.polygons.push_back({{{2, 0, 1}, {2, 1, 1}, {4, 1, 1}, {4, 0, 1}}, 2});
  const RadiosityMesh mesh = meshUniformly(scene, 0.5);
  const EmitterSampler sampler(mesh);
  ASSERT_FALSE(sampler.empty());
  SampleStream stream(42);
  const int n = 70000;
  int bright = 0;
  for (int i = 0; i < n; ++i) {
    const double u0 = stream.uniform(), u1 = stream.uniform(), u2 = stream.uniform();
    const EmitterSample s = sampler.sample(u0, u1, u2);
    EXPECT_EQ(s.position.z, 1.0);
    EXPECT_EQ(s.normal, Vec3(0, 0, -1));
    const bool isBright = s.E.r == 3.0;
    ASSERT_TRUE(isBright ? s.position.x >= 2.0 && s.position.x <= 4.0 : s.position.x >= 0.0 && s.position.x <= 1.0);
    ASSERT_GE(s.position.y, 0.0);
    ASSERT_LE(s.position.y, 1.0);
    // Total power 7: density per unit area E / 7.
    ASSERT_NEAR(s.pdfArea, s.E.r / 7.0, 1e-12);
    bright += isBright;
  }
  // 6/7 of the picks, within 5 standard deviations (sd = sqrt(n p (1-p)) ~ 92).
  EXPECT_NEAR(bright, n * 6.0 / 7.0, 5 * 92.0);
}

TEST(EmitterSamplerTest, NoEmittersLeavesItEmpty) {
  Scene scene;
  scene.materials = {{"floor", {0.5, 0.5, 0.5}, {0, 0, 0}}};
  scene.polygons.push_back({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, 0});
  EXPECT_TRUE(EmitterSampler(meshUniformly(scene, 1.0)).empty());
}

TEST(HemisphereSamplingTest, CosineWeightedDirectionsHaveMeanCosineTwoThirds) {
  // E[cos] under the density cos / pi is 2/3; every direction lies above the surface.
  for (Vec3 n : {Vec3(0, 0, 1), Vec3(0, 0, -1), glm::normalize(Vec3(1, -2, 0.5))}) {
    SampleStream stream(3);
    double sum = 0.0;
    const int count = 20000;
    for (int i = 0; i < count; ++i) {
      const double u1 = stream.uniform(), u2 = stream.uniform();
      const Vec3 w = cosineWeightedDirection(n, u1, u2);
      ASSERT_NEAR(glm::length(w), 1.0, 1e-12);
      ASSERT_GE(glm::dot(w, n), 0.0);
      sum += glm::dot(w, n);
    }
    // sd of cos is sqrt(1/2 - 4/9) ~ 0.236: 5 standard errors.
    EXPECT_NEAR(sum / count, 2.0 / 3.0, 5 * 0.236 / std::sqrt(double(count))) << n.x << " " << n.y << " " << n.z;
  }
}

}  // namespace
}  // namespace radview
