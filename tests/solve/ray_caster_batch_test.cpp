// The solver's batched visibility (RayCaster::occluded over many segments, one coherent
// stream) answers as one ray at a time does, ray for ray: in the Cornell box, from points on
// the floor (many in the blocks' shadows) to points on the light, in streams of every length
// the solver makes and longer, and in the solver's form, one point to many.
#include "solve/ray_caster.h"

#include "tests/solve/cornell_box.h"

#include <gtest/gtest.h>

#include <random>

namespace radview {
namespace {

TEST(RayCasterBatchTest, StreamsAnswerAsSingleRaysDo) {
  const Scene scene = test::cornellBox();
  const RayCaster caster(scene);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Vec3 up(0, 1, 0), down(0, -1, 0);
  size_t blocked = 0, total = 0;
  for (size_t count : {1, 3, 16, 17, 64, 1000}) {
    std::vector<Segment> segments;
    for (size_t i = 0; i < count; ++i) {
      const Vec3 floor(552.0 * unit(random), 0.0, 559.0 * unit(random));
      const Vec3 light(213.0 + 130.0 * unit(random), 548.7, 227.0 + 105.0 * unit(random));
      segments.push_back({floor, up, light, down});
    }
    std::vector<uint8_t> batch(count, 2);
    caster.occluded(segments.data(), count, batch.data());
    for (size_t i = 0; i < count; ++i) {
      EXPECT_EQ(batch[i], caster.occluded(segments[i]) ? 1 : 0) << "stream of " << count << ", ray " << i;
      blocked += batch[i];
    }
    total += count;
  }
  // Both answers occur: the blocks shadow part of the floor.
  EXPECT_GT(blocked, total / 20);
  EXPECT_LT(blocked, total / 2);
  caster.occluded(nullptr, 0, nullptr);  // an empty stream is no call
}

// The solver's form of the stream, one receiving point to many points of one patch, casts the
// same rays: the same answers as its segments', from floor points in shadow and in the open.
TEST(RayCasterBatchTest, StreamsFromOnePointAnswerAsTheirSegmentsDo) {
  const Scene scene = test::cornellBox();
  const RayCaster caster(scene);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Vec3 up(0, 1, 0), down(0, -1, 0);
  size_t blocked = 0, total = 0;
  for (int point = 0; point < 200; ++point) {
    const Vec3 floor(552.0 * unit(random), 0.0, 559.0 * unit(random));
    std::vector<Vec3> light;
    std::vector<Segment> segments;
    for (int k = 0; k < 16; ++k) {
      light.push_back({213.0 + 130.0 * unit(random), 548.7, 227.0 + 105.0 * unit(random)});
      segments.push_back({floor, up, light.back(), down});
    }
    std::vector<uint8_t> fromPoint(light.size(), 2), fromSegments(light.size(), 2);
    caster.occludedFrom(floor, up, light.data(), light.size(), down, fromPoint.data());
    caster.occluded(segments.data(), segments.size(), fromSegments.data());
    EXPECT_EQ(fromPoint, fromSegments) << "floor point " << point;
    for (uint8_t b : fromPoint) blocked += b;
    total += light.size();
  }
  EXPECT_GT(blocked, total / 20);
  EXPECT_LT(blocked, total / 2);
  caster.occludedFrom(Vec3(0.0), up, nullptr, 0, down, nullptr);  // an empty stream is no call
}

}  // namespace
}  // namespace radview
