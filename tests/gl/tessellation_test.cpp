// GPU tessellation of the Bezier pieces: the adaptive level meets its tolerance against the
// exact per-pixel evaluation on the bundled scenes, and no level or view opens cracks or
// makes NaN.
#include "core/camera.h"
#include "gl/egl_context.h"
#include "gl/mesh_renderer.h"
#include "import/load_file.h"
#include "scene/camera_presets.h"
#include "solve/direct_light.h"
#include "tests/gl/oblique_view.h"
#include "tests/sanitizer/sanitizer_build.h"

#include <gtest/gtest.h>

#include <algorithm>
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

Renders renderBoth(const RadiosityMesh& mesh, const Camera& camera, Method method, int tessellation,
                   double exposure = 0.0, double tolerance = 0.5 / 255) {
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
  settings.tessellationTolerance = tolerance;
  renderer.render(camera, settings, 160, 160);
  out.tessellatedDisplay = renderer.readDisplay();
  out.tessellatedLinear = renderer.readLinear();
  out.statistics = renderer.tessellationStatistics();
  return out;
}

double srgb(double v) {
  v = std::clamp(v, 0.0, 1.0);
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

// The display error of the tessellated image against the exact one, from the linear
// read-backs through the display transform (not the 8-bit images, whose rounding would hide
// or double it), over pixels whose 3 x 3 neighbourhood is surface in both images (at the
// silhouette a pixel centre may fall on either side of an edge the two draws place a float
// apart). Likewise where two surfaces meet at an edge (the short block's lit top and its dark
// front): a GPU's rasteriser snaps corners to its sub-pixel grid and may give a pixel centre
// there to the other surface in one of the draws. Such a pixel (more than 16 steps off, beside
// a jump of more than 16 steps in the exact image, and within the tolerance of an exact
// neighbour: the other surface's value, not a wrong one) is left out, one in a thousand at most.
// Asserted against the tolerance for the worst pixel, with 1 % for float rounding.
void expectWithinTolerance(const Renders& r, double exposure, double tolerance, const std::string& what) {
  const int w = r.exactLinear.width, h = r.exactLinear.height;
  const double s = std::exp2(exposure);
  auto display = [&](int x, int y, int c) {
    return srgb(s * r.exactLinear.rgba[(size_t(std::clamp(y, 0, h - 1)) * w + std::clamp(x, 0, w - 1)) * 4 + c]);
  };
  auto besideJump = [&](int x, int y) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        for (int c = 0; c < 3; ++c)
          if (std::abs(display(x + dx, y + dy, c) - display(x, y, c)) > 16.0 / 255) return true;
    return false;
  };
  auto neighbourValue = [&](int x, int y) {  // the tessellated pixel shows an exact neighbour
    const size_t i = (size_t(y) * w + x) * 4;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        double error = 0.0;
        for (int c = 0; c < 3; ++c)
          error = std::max(error, std::abs(display(x + dx, y + dy, c) - srgb(s * r.tessellatedLinear.rgba[i + c])));
        if (error <= 1.01 * tolerance) return true;
      }
    return false;
  };
  auto covered = [&](int x, int y) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int px = std::clamp(x + dx, 0, w - 1), py = std::clamp(y + dy, 0, h - 1);
        const size_t i = (size_t(py) * w + px) * 4 + 3;
        if (r.exactLinear.rgba[i] == 0.0f || r.tessellatedLinear.rgba[i] == 0.0f) return false;
      }
    return true;
  };
  size_t pixels = 0, switched = 0;
  double worst = 0.0;
  int worstX = -1, worstY = -1;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!covered(x, y)) continue;
      const size_t i = (size_t(y) * w + x) * 4;
      double error = 0.0;
      for (int c = 0; c < 3; ++c) {
        const double e = std::abs(srgb(s * r.exactLinear.rgba[i + c]) - srgb(s * r.tessellatedLinear.rgba[i + c]));
        error = std::isnan(e) ? INFINITY : std::max(error, e);
      }
      if (error > 16.0 / 255 && error != INFINITY && besideJump(x, y) && neighbourValue(x, y)) {
        ++switched;
        continue;
      }
      if (error > worst) worst = error, worstX = x, worstY = y;
      ++pixels;
    }
  std::cout << what << ": " << pixels << " pixels (" << switched
            << " beside an edge, on the other surface, left out), worst display error " << worst * 255
            << " / tolerance " << tolerance * 255 << " 8-bit steps at pixel (" << worstX << ", " << worstY
            << ") of the read-back; mean level " << r.statistics.averageLevel << ", " << r.statistics.draws
            << " draws\n";
  EXPECT_GT(pixels, 2000u) << what;
  EXPECT_LE(switched, (pixels + switched) / 1000) << what;
  EXPECT_LE(worst, 1.01 * tolerance) << what;
}

Camera faceOnSquare() {  // the unit squares of discontinuities.gltf and t_vertices.gltf
  Camera c;
  c.eye = {0.5, 0.5, 1.2};
  c.target = {0.5, 0.5, 0.0};
  c.zNear = 0.1;
  c.zFar = 10;
  return c;
}

Camera obliqueOnQuad() {  // fig9_8_quad.gltf, centred at the origin
  Camera c;
  c.eye = {0.3, -1.1, 0.9};
  c.up = {0, 0, 1};
  c.zNear = 0.1;
  c.zFar = 10;
  return c;
}

TEST(Tessellation, AdaptiveMeetsItsToleranceOnEveryBundledScene) {
  const LoadedFile cornell = loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/cornell_box.gltf");
  const RadiosityMesh cornellMesh = bundled("cornell_box.gltf");
  const struct {
    std::string name;
    RadiosityMesh mesh;
    Camera camera;
  } scenes[] = {
      {"cornell box", cornellMesh, cameraFromSpec("file", cornellMesh.bounds(), cornell.scene.cameras)},
      {"discontinuities", bundled("discontinuities.gltf"), test::obliqueView()},
      {"t-vertices", bundled("t_vertices.gltf"), faceOnSquare()},
      {"fig. 9.8 quad", bundled("fig9_8_quad.gltf"), obliqueOnQuad()},
  };
  for (const auto& scene : scenes)
    for (Method method : {Method::CloughTocher, Method::C1Quadratic})
      for (double exposure : {0.0, 1.5})
        for (double steps : {0.5, 2.0}) {
          // The Cornell box's adaptive draws take 6 to 17 minutes under the sanitizers
          // (tests/sanitizer/sanitizer_build.h); there the three small scenes stand for it.
          if (test::kSanitizerBuild && &scene == &scenes[0]) continue;
          const std::string what = scene.name + ", " + methodName(method) + ", exposure " + std::to_string(exposure) +
                                   ", tolerance " + std::to_string(steps);
          expectWithinTolerance(
              renderBoth(scene.mesh, scene.camera, method, kAdaptiveTessellation, exposure, steps / 255), exposure,
              steps / 255, what);
        }
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

TEST(Tessellation, NoLevelOrViewOpensCracks) {
  // Fixed levels 1 and 64, and adaptive levels (where neighbours' levels differ and only the
  // shared outer levels keep them joined), head-on and grazing, for both C1 methods.
  Camera grazing = test::obliqueView();
  grazing.eye = {0.5, -1.5, 0.12};  // 4 degrees above the plane of the square
  for (const char* name : {"discontinuities.gltf", "t_vertices.gltf"}) {
    const RadiosityMesh mesh = bundled(name);
    for (Method method : {Method::CloughTocher, Method::C1Quadratic})
      for (int level : {1, 64, kAdaptiveTessellation})
        for (const Camera& camera : {test::obliqueView(), grazing}) {
          const std::string what = std::string(name) + " " + methodName(method) + " level " + std::to_string(level) +
                                   (&camera == &grazing ? " grazing" : "");
          expectNoCracks(renderBoth(mesh, camera, method, level, 0.0, 0.25 / 255), what);
        }
  }
}

TEST(Tessellation, LevelSixtyFourIsSplitIntoDrawsLlvmpipeCanTake) {
  // 288 Clough-Tocher pieces at level 64 generate ~1.2 million triangles: many draws of at most
  // 50k each, and the image still matches the exact one (so no geometry went missing).
  const Renders r = renderBoth(bundled("discontinuities.gltf"), test::obliqueView(), Method::CloughTocher, 64);
  EXPECT_GE(r.statistics.draws, 24u);
  expectWithinTolerance(r, 0.0, 0.5 / 255, "level 64");
}

}  // namespace
}  // namespace radview::gl
