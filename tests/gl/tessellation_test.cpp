// GPU tessellation of the Bezier pieces: the adaptive level meets its tolerance against the
// exact per-pixel evaluation on the bundled scenes, and no level or view opens cracks or
// makes NaN.
#include "core/camera.h"
#include "gl/egl_context.h"
#include "gl/mesh_renderer.h"
#include "mesh/load_file.h"
#include "solve/direct_light.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace radview::gl {
namespace {

RadiosityMesh bundled(const std::string& name) {
  const LoadedFile file = loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/" + name);
  return file.isSolution ? file.mesh : meshAndLight(file.scene, defaultElementSize(file.scene));
}

struct Renders {
  Image exactDisplay, tessellatedDisplay;
  LinearImage exactLinear, tessellatedLinear;
  TessellationStatistics statistics;
};

Renders renderBoth(const RadiosityMesh& mesh, const Camera& camera, ShadingMethod method, int tessellation,
                   double exposure = 0.0) {
  EglContext context;
  MeshRenderer renderer;
  renderer.setMesh(mesh);
  RenderSettings settings;
  settings.method = method;
  settings.exposure = exposure;
  Renders out;
  renderer.render(camera, settings, 160, 160);
  out.exactDisplay = renderer.readDisplay();
  out.exactLinear = renderer.readLinear();
  settings.tessellation = tessellation;
  renderer.render(camera, settings, 160, 160);
  out.tessellatedDisplay = renderer.readDisplay();
  out.tessellatedLinear = renderer.readLinear();
  out.statistics = renderer.tessellationStatistics();
  return out;
}

// The display images differ by at most one 8-bit step (a tolerance of half a step, then each
// rounds to the nearest step), except at a few pixels on element edges where the two draws
// cover a pixel centre from different sides.
void expectWithinTolerance(const Renders& r, const std::string& what) {
  size_t pixels = 0, within = 0;
  int worst = 0;
  for (size_t i = 0; i < r.exactDisplay.rgba.size(); i += 4) {
    if (r.exactLinear.rgba[i + 3] == 0.0f) continue;
    int difference = 0;
    for (int c = 0; c < 3; ++c)
      difference = std::max(difference, std::abs(int(r.exactDisplay.rgba[i + c]) - int(r.tessellatedDisplay.rgba[i + c])));
    ++pixels;
    within += difference <= 1;
    worst = std::max(worst, difference);
  }
  std::cout << what << ": " << pixels << " pixels, " << within << " within one 8-bit step, worst " << worst
            << " steps; mean level " << r.statistics.averageLevel << ", " << r.statistics.draws << " draws\n";
  EXPECT_GT(pixels, 2000u) << what;
  EXPECT_GE(within, pixels - pixels / 200) << what;
}

Camera oblique() {
  Camera c;
  c.eye = {0.5, -0.6, 1.1};
  c.target = {0.5, 0.5, 0.0};
  c.zNear = 0.1;
  c.zFar = 10;
  return c;
}

TEST(Tessellation, AdaptiveMeetsItsToleranceOnTheDiscontinuityMesh) {
  const RadiosityMesh mesh = bundled("discontinuities.gltf");
  for (ShadingMethod method : {ShadingMethod::CloughTocher, ShadingMethod::C1Quadratic})
    for (double exposure : {0.0, 1.5})
      expectWithinTolerance(renderBoth(mesh, oblique(), method, kAdaptiveTessellation, exposure),
                            shadingMethodNames()[int(method)] + " exposure " + std::to_string(exposure));
}

TEST(Tessellation, AdaptiveMeetsItsToleranceOnTheCornellBox) {
  const LoadedFile file = loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/cornell_box.gltf");
  const RadiosityMesh mesh = bundled("cornell_box.gltf");
  Camera camera = cameraFromSpec("file", mesh.bounds(), file.scene.cameras);
  expectWithinTolerance(renderBoth(mesh, camera, ShadingMethod::CloughTocher, kAdaptiveTessellation), "cornell box");
}

TEST(Tessellation, AdaptiveMeetsItsToleranceOnTheFig98Quad) {
  Camera camera;
  camera.eye = {0.3, -1.1, 0.9};
  camera.up = {0, 0, 1};
  camera.zNear = 0.1;
  camera.zFar = 10;
  expectWithinTolerance(renderBoth(bundled("fig9_8_quad.gltf"), camera, ShadingMethod::CloughTocher,
                                   kAdaptiveTessellation),
                        "fig. 9.8 quad");
}

// Every pixel the exact evaluation covers, the tessellated draw covers too (no crack between
// patches), and nothing is NaN.
void expectNoCracks(const Renders& r, const std::string& what) {
  size_t covered = 0, cracks = 0, nans = 0;
  for (size_t i = 0; i < r.exactLinear.rgba.size(); i += 4) {
    for (int c = 0; c < 4; ++c) nans += std::isnan(r.tessellatedLinear.rgba[i + c]);
    if (r.exactLinear.rgba[i + 3] == 0.0f) continue;
    ++covered;
    cracks += r.tessellatedLinear.rgba[i + 3] == 0.0f;
  }
  EXPECT_GT(covered, 300u) << what;  // a grazing view covers few pixels
  EXPECT_EQ(cracks, 0u) << what;
  EXPECT_EQ(nans, 0u) << what;
}

TEST(Tessellation, LevelsOneAndSixtyFourAndGrazingViewsOpenNoCracks) {
  const RadiosityMesh mesh = bundled("discontinuities.gltf");
  Camera grazing = oblique();
  grazing.eye = {0.5, -1.5, 0.12};  // 4 degrees above the plane of the square
  for (int level : {1, 64}) {
    expectNoCracks(renderBoth(mesh, oblique(), ShadingMethod::CloughTocher, level), "level " + std::to_string(level));
    expectNoCracks(renderBoth(mesh, grazing, ShadingMethod::CloughTocher, level),
                   "grazing, level " + std::to_string(level));
  }
}

TEST(Tessellation, LevelSixtyFourIsSplitIntoDrawsLlvmpipeCanTake) {
  // 288 Clough-Tocher pieces at level 64 generate ~1.2 million triangles: many draws of at most
  // 50k each, and the image still matches the exact one (so no geometry went missing).
  const Renders r = renderBoth(bundled("discontinuities.gltf"), oblique(), ShadingMethod::CloughTocher, 64);
  EXPECT_GE(r.statistics.draws, 24u);
  expectWithinTolerance(r, "level 64");
}

}  // namespace
}  // namespace radview::gl
