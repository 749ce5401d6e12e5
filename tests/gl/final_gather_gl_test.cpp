// The final gather against the GL renderer on a scene where B^ is exact (the direct light of an
// unoccluded scene, meshAndLight on a fine mesh): the two must cover the same pixels, and agree
// on the values up to the gather's noise.
#include "core/camera.h"
#include "gather/final_gather.h"
#include "gl/egl_context.h"
#include "gl/mesh_renderer.h"
#include "solve/direct_light.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace radview {
namespace {

TEST(FinalGatherGlTest, CoversTheSamePixelsAsTheGlRendererAndAgreesWithAnExactSolution) {
  // A floor under a square light facing it: nothing occludes, so meshAndLight is exact at the
  // nodes, and the light's own B^ is its E (it reflects nothing), so the gather's indirect part
  // is 0 and its direct part is the same exact integral.
  Scene scene;
  scene.materials = {{"floor", {0.5, 0.4, 0.3}, {0, 0, 0}}, {"light", {0, 0, 0}, {2, 2, 2}}};
  scene.polygons.push_back({{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, 0});
  scene.polygons.push_back({{{-0.3, -0.3, 0.8}, {-0.3, 0.3, 0.8}, {0.3, 0.3, 0.8}, {0.3, -0.3, 0.8}}, 1});
  const RadiosityMesh mesh = meshAndLight(scene, 0.04);

  const int width = 96, height = 72;
  Camera camera;
  camera.eye = {0.4, -2.6, 1.9};
  camera.target = {0.0, 0.1, 0.0};
  camera.up = {0, 0, 1};
  fitClipPlanes(camera, mesh.bounds());

  gl::EglContext context;
  gl::MeshRenderer renderer;
  renderer.setMesh(mesh);
  renderer.render(camera, gl::RenderSettings{}, width, height);
  const LinearImage glImage = renderer.readLinear();

  GatherSettings settings;
  settings.width = width;
  settings.height = height;
  settings.camera = camera;
  FinalGather gather(mesh, settings);
  gather.addPasses(32);
  const LinearImage gathered = gather.image();

  size_t compared = 0, coverageMismatches = 0;
  double glSum = 0.0, gatherSum = 0.0;
  for (size_t i = 0; i < size_t(width) * size_t(height); ++i) {
    const float glAlpha = glImage.rgba[4 * i + 3], gatherAlpha = gathered.rgba[4 * i + 3];
    // A pixel the gather sees wholly must be drawn by GL at its centre, and one the gather never
    // sees must be empty in GL: a half-pixel shift or a flipped row order breaks both.
    if ((gatherAlpha == 1.0f && glAlpha == 0.0f) || (gatherAlpha == 0.0f && glAlpha > 0.0f)) ++coverageMismatches;
    if (gatherAlpha == 1.0f && glAlpha > 0.0f) {
      glSum += glImage.rgba[4 * i];
      gatherSum += gathered.rgba[4 * i];
      ++compared;
    }
  }
  std::printf(
      "final gather vs GL: %zu pixels compared, mean B (red) GL %.5f, gather %.5f (%+.2f%%), "
      "%zu coverage mismatches\n",
      compared, glSum / double(compared), gatherSum / double(compared), 100.0 * (gatherSum - glSum) / glSum,
      coverageMismatches);
  EXPECT_GT(compared, size_t(width * height / 4));
  EXPECT_EQ(coverageMismatches, 0u);
  // Linear interpolation of exact nodal values on 4 cm elements is within a fraction of a
  // percent of the exact field here; the gather's mean over thousands of pixels is as close.
  EXPECT_NEAR(gatherSum / glSum, 1.0, 0.01);
}

}  // namespace
}  // namespace radview
