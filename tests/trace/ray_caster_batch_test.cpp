// The solver's batched visibility (RayCaster::occluded over many segments, one coherent
// stream) answers as one ray at a time does, ray for ray: in the Cornell box, from points on
// the floor (many in the blocks' shadows) to points on the light, in streams of every length
// the solver makes and longer, and in the solver's form, one point to many.
#include "trace/ray_caster.h"

#include "tests/solve/cornell_box.h"

#include <gtest/gtest.h>

#include <random>

namespace radview {
namespace {

// Random points on the floor and on the light, their coordinates drawn in a fixed order (the
// order in which a constructor's arguments are evaluated differs between compilers, and the
// counts below depend on which point is drawn).
struct CornellPoints {
  std::mt19937 random;
  std::uniform_real_distribution<double> unit{0.0, 1.0};
  explicit CornellPoints(unsigned seed) : random(seed) {}
  Vec3 onFloor() {
    const double x = 552.0 * unit(random), z = 559.0 * unit(random);
    return {x, 0.0, z};
  }
  Vec3 onLight() {
    const double x = 213.0 + 130.0 * unit(random), z = 227.0 + 105.0 * unit(random);
    return {x, 548.7, z};
  }
};

TEST(RayCasterBatchTest, StreamsAnswerAsSingleRaysDo) {
  const Scene scene = test::cornellBox();
  const RayCaster caster(scene);
  CornellPoints points(7);
  const Vec3 up(0, 1, 0), down(0, -1, 0);
  size_t blocked = 0, total = 0;
  for (size_t count : {1, 3, 16, 17, 64, 1000}) {
    std::vector<Segment> segments;
    for (size_t i = 0; i < count; ++i) {
      const Vec3 floor = points.onFloor();
      const Vec3 light = points.onLight();
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
  // Both answers occur, each for a twentieth of the rays or more: the blocks shadow part of
  // the floor (about half of these rays are blocked).
  EXPECT_GT(blocked, total / 20);
  EXPECT_LT(blocked, total - total / 20);
  caster.occluded(nullptr, 0, nullptr);  // an empty stream is no call
}

// The solver's form of the stream, one receiving point to many points of one patch, casts the
// same rays: the same answers as its segments', from floor points in shadow and in the open.
TEST(RayCasterBatchTest, StreamsFromOnePointAnswerAsTheirSegmentsDo) {
  const Scene scene = test::cornellBox();
  const RayCaster caster(scene);
  CornellPoints points(11);
  const Vec3 up(0, 1, 0), down(0, -1, 0);
  size_t blocked = 0, total = 0;
  for (int point = 0; point < 200; ++point) {
    const Vec3 floor = points.onFloor();
    std::vector<Vec3> light;
    std::vector<Segment> segments;
    for (int k = 0; k < 16; ++k) {
      light.push_back(points.onLight());
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
  EXPECT_LT(blocked, total - total / 20);
  caster.occludedFrom(Vec3(0.0), up, nullptr, 0, down, nullptr);  // an empty stream is no call
}

}  // namespace
}  // namespace radview
