#include "trace/camera_rays.h"

#include "gather/final_gather.h"
#include "tests/gather/gather_scenes.h"
#include "tests/test_print.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace radview {
namespace {

Camera tiltedCamera() {
  Camera camera;
  camera.eye = {1.0, 2.0, 3.0};
  camera.target = {0.0, 0.5, 0.0};
  camera.up = {0.1, 1.0, 0.0};
  camera.yfov = glm::radians(50.0);
  fitClipPlanes(camera, Bounds{{-3, -3, -3}, {3, 3, 3}});
  return camera;
}

// Where the GL pipeline puts a world point: pixel coordinates with row 0 at the top (the
// viewport map of window y, which runs up, flipped as readback flips it).
Vec2 projected(const Camera& camera, int width, int height, const Vec3& p) {
  const glm::dvec4 clip = camera.clipFromWorld(double(width) / height) * glm::dvec4(p, 1.0);
  const Vec3 ndc = Vec3(clip) / clip.w;
  return {(ndc.x + 1.0) / 2.0 * width, height - (ndc.y + 1.0) / 2.0 * height};
}

TEST(CameraRaysTest, EveryPointOnARayProjectsBackToItsImagePoint) {
  const Camera camera = tiltedCamera();
  const int width = 200, height = 100;
  const CameraRays rays(camera, width, height);
  for (Vec2 pixel :
       {Vec2(0.5, 0.5), Vec2(199.5, 0.5), Vec2(0.5, 99.5), Vec2(150.5, 20.5), Vec2(0.0, 100.0), Vec2(37.25, 81.75)}) {
    const Ray ray = rays.through(pixel.x, pixel.y);
    EXPECT_EQ(ray.origin, camera.eye);
    EXPECT_NEAR(glm::length(ray.direction), 1.0, 1e-12);
    for (double t : {0.5, 2.0, 7.0}) {
      const Vec2 back = projected(camera, width, height, ray.origin + t * ray.direction);
      EXPECT_NEAR(back.x, pixel.x, 1e-7) << pixel.x << ' ' << pixel.y << " t " << t;
      EXPECT_NEAR(back.y, pixel.y, 1e-7) << pixel.x << ' ' << pixel.y << " t " << t;
    }
  }
}

TEST(CameraRaysTest, GatherCoverageMatchesTheProjectedPolygon) {
  // The receiver alone, seen obliquely: pixels whose whole square lies inside its projection
  // are covered by every sample, those outside its projected bounding box by none.
  Scene scene = test::receiverUnderSquareEmitter();
  scene.polygons.pop_back();
  scene.materials[0].E = {1, 1, 1};  // emitter sampling has something to sample
  RadiosityMesh mesh = meshUniformly(scene, 1.0);
  GatherSettings settings;
  settings.width = 48;
  settings.height = 32;
  settings.camera = tiltedCamera();
  settings.camera.eye = {1.5, -4.0, 3.0};
  settings.camera.target = {0.2, 0.0, 0.0};
  settings.camera.up = {0.0, 0.0, 1.0};
  FinalGather gather(mesh, settings);
  gather.addPasses(4);
  const LinearImage image = gather.image();

  std::vector<Vec2> corners;
  for (const Vec3& v : scene.polygons[0].vertices)
    corners.push_back(projected(settings.camera, settings.width, settings.height, v));
  // Inside a CCW-or-CW convex polygon: on the same side of every edge.
  auto inside = [&](Vec2 p) {
    int sign = 0;
    for (size_t k = 0; k < corners.size(); ++k) {
      const Vec2 a = corners[k], b = corners[(k + 1) % corners.size()];
      const double cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
      const int s = cross > 1e-6 ? 1 : cross < -1e-6 ? -1 : 0;
      if (s == 0 || (sign != 0 && s != sign)) return false;
      sign = s;
    }
    return true;
  };
  Vec2 lo(1e9), hi(-1e9);
  for (Vec2 c : corners) lo = glm::min(lo, c), hi = glm::max(hi, c);
  size_t full = 0, empty = 0;
  for (int y = 0; y < settings.height; ++y)
    for (int x = 0; x < settings.width; ++x) {
      const float alpha = image.rgba[(size_t(y) * size_t(settings.width) + size_t(x)) * 4 + 3];
      if (inside({x, y}) && inside({x + 1, y}) && inside({x, y + 1}) && inside({x + 1, y + 1})) {
        EXPECT_EQ(alpha, 1.0f) << x << ' ' << y;
        ++full;
      }
      if (x + 1 < lo.x || x > hi.x || y + 1 < lo.y || y > hi.y) {
        EXPECT_EQ(alpha, 0.0f) << x << ' ' << y;
        ++empty;
      }
    }
  EXPECT_GT(full, 200u);
  EXPECT_GT(empty, 50u);
}

}  // namespace
}  // namespace radview
