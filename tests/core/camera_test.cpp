#include "core/camera.h"
#include "core/error.h"
#include "scene/camera_presets.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

namespace radview {
namespace {

Bounds unitBox() {
  Bounds b;
  b.extend({-1, -1, -1});
  b.extend({1, 1, 1});
  return b;
}

TEST(Camera, PresetsLookAtTheCentreAndEncloseTheBounds) {
  for (const std::string& name : cameraPresetNames()) {
    if (name == "file") continue;
    const Camera c = cameraFromSpec(name, unitBox(), {});
    EXPECT_NEAR(glm::length(c.target), 0.0, 1e-12) << name;
    const double distance = glm::length(c.eye - c.target);
    EXPECT_GT(distance, std::sqrt(3.0)) << name;
    EXPECT_LT(c.zNear, distance - std::sqrt(3.0) + 1e-9) << name;
    EXPECT_GT(c.zFar, distance + std::sqrt(3.0) - 1e-9) << name;
  }
}

TEST(Camera, EmptySpecPrefersTheFileCamera) {
  SceneCamera file;
  file.eye = {0, 0, 5};
  file.target = {0, 0, 0};
  file.yfov = 0.5;
  EXPECT_DOUBLE_EQ(cameraFromSpec("", unitBox(), {file}).yfov, 0.5);
  EXPECT_EQ(cameraFromSpec("", unitBox(), {}).eye, cameraFromSpec("front", unitBox(), {}).eye);
}

TEST(Camera, EyeTargetUpSpec) {
  const Camera c = cameraFromSpec("0,0,4/0,0,0/1,0,0", unitBox(), {});
  EXPECT_EQ(c.eye, Vec3(0, 0, 4));
  EXPECT_EQ(c.up, Vec3(1, 0, 0));
}

TEST(Camera, BadSpecsAreClearErrors) {
  for (const char* spec :
       {"nowhere", "1,2/3,4,5", "0,0,0/0,0,0", "0,0,1/0,0,0/0,0,1", "0,0,1/0,0,nan", "a,b,c/0,0,0"}) {
    try {
      cameraFromSpec(spec, unitBox(), {});
      ADD_FAILURE() << "accepted " << spec;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(spec), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(cameraFromSpec("file", unitBox(), {}), Error);
}

TEST(Camera, RollTurnsTheImageClockwise) {
  // Looking down -z with y up: a point to the right of centre must move down on screen.
  Camera c = cameraFromSpec("0,0,5/0,0,0/0,1,0", unitBox(), {});
  roll(c, glm::radians(45.0));
  const glm::dvec4 clip = c.clipFromWorld(1.0) * glm::dvec4(1.0, 0.0, 0.0, 1.0);
  EXPECT_GT(clip.x / clip.w, 0.0);
  EXPECT_LT(clip.y / clip.w, 0.0);
}

TEST(Camera, RollBy45DegreesEightTimesIsTheIdentity) {
  Camera c = cameraFromSpec("iso", unitBox(), {});
  const Vec3 up = c.up;
  for (int i = 0; i < 8; ++i) roll(c, glm::radians(45.0));
  EXPECT_NEAR(glm::length(c.up - up), 0.0, 1e-12);
}

TEST(Camera, OrbitKeepsTheDistanceAndNeverFlipsOverThePole) {
  Camera c = cameraFromSpec("front", unitBox(), {});
  const double distance = glm::length(c.eye - c.target);
  for (int i = 0; i < 100; ++i) orbit(c, 0.1, 0.2);
  EXPECT_NEAR(glm::length(c.eye - c.target), distance, 1e-9);
  EXPECT_GT(glm::length(glm::cross(c.forward(), c.up)), 1e-3);
}

// A view narrower than tall widens the vertical field so its width covers the camera's
// vertical field: a point at the edge of that field stays at the view's side edge.
TEST(Camera, FramedForANarrowViewKeepsTheFieldAcrossItsWidth) {
  Camera c;
  c.yfov = glm::radians(45.0);
  EXPECT_EQ(framedFor(c, 1.6).yfov, c.yfov);
  EXPECT_EQ(framedFor(c, 1.0).yfov, c.yfov);
  const double aspect = 0.5;
  const Camera framed = framedFor(c, aspect);
  EXPECT_GT(framed.yfov, c.yfov);
  // A point on the camera's vertical field's edge, turned to the side: x_ndc = 1.
  const double half = std::tan(0.5 * c.yfov);
  const glm::dvec4 clip = framed.clipFromView(aspect) * glm::dvec4(half, 0.0, -1.0, 1.0);
  EXPECT_NEAR(clip.x / clip.w, 1.0, 1e-12);
}

}  // namespace
}  // namespace radview
