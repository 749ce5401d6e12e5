// The bench's error estimate against a known answer: on a closed-form scene (one bounce, no
// occlusion: tests/closed_form_scenes.h) the exact image is known at every pixel centre, so each
// row's exact error is known too. The estimate the bench makes from the final gather must agree
// with it within its own 95 % interval (C&W eq. 9.9 integrates the exact B^ here: the gather's
// expectation is the closed form). The gather's control variates hold this scene's light
// exactly, so its runs have no noise to speak of; the same runs with noise added (Gaussian,
// independent per pixel and run) must still give estimates that cover the exact errors.
#include "bench/bench_reference.h"
#include "bench/image_error.h"
#include "bench/mach_bands.h"
#include "core/camera.h"
#include "gather/final_gather.h"
#include "gl/egl_context.h"
#include "gl/mesh_renderer.h"
#include "mesh/uniform_mesher.h"
#include "tests/closed_form_scenes.h"
#include "trace/camera_rays.h"
#include "trace/visible_elements.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

namespace radview {
namespace {

TEST(BenchEstimate, AgreesWithTheExactErrorOfEachRowWithinItsInterval) {
  const test::ClosedFormScene closedForm = test::emitterOverSquare(30.0);
  RadiosityMesh mesh = meshUniformly(closedForm.scene, 1.0 / 8.0);
  for (const Element& e : mesh.elements)
    for (uint32_t n : e.corners)
      mesh.nodes[n].B = e.material == 1 ? closedForm.E : closedForm.B(mesh.nodes[n].position);

  const int width = 96, height = 96;
  Camera camera;
  camera.eye = {0.5, 0.45, 1.35};  // below the emitter: it never hides the receiver
  camera.target = {0.5, 0.0, 0.5};
  camera.up = {0, 1, 0};
  fitClipPlanes(camera, mesh.bounds());

  // The exact image at every pixel centre: the closed form where the eye ray meets the
  // receiver (y = 0), the emitter's E elsewhere (it reflects nothing).
  const CameraRays rays(camera, width, height);
  LinearImage exact{width, height, std::vector<float>(size_t(width) * height * 4, 1.0f)};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Ray ray = rays.through(x + 0.5, y + 0.5);
      Rgb B = closedForm.E;
      if (ray.direction.y < 0.0) B = closedForm.B(ray.origin - ray.origin.y / ray.direction.y * ray.direction);
      for (int c = 0; c < 3; ++c) exact.rgba[4 * (size_t(y) * width + x) + size_t(c)] = float(B[c]);
    }

  const std::vector<int32_t> elementAt = visibleElements(mesh, camera, width, height);
  const std::vector<char> interior = interiorPixels(mesh, elementAt, width, height);
  std::vector<uint32_t> pixels;
  for (size_t p = 0; p < interior.size(); ++p)
    if (interior[p]) pixels.push_back(uint32_t(p));
  const EdgeStencils stencils = edgeStencils(mesh, elementAt, width, height);
  BenchReference truth(width, height, pixels, stencils.smooth, stencils.c0, 1.0);
  truth.setExact(exact);
  BenchReference gathered(width, height, pixels, stencils.smooth, stencils.c0, 1.0);
  GatherSettings settings;
  settings.width = width;
  settings.height = height;
  settings.camera = camera;
  settings.runs = 4;
  settings.pixelCentres = true;
  FinalGather gather(mesh, settings);
  gather.addPasses(64);
  std::vector<LinearImage> runs;
  for (int r = 0; r < settings.runs; ++r) runs.push_back(gather.runImage(r));
  std::vector<LinearImage> noisyRuns = runs;
  std::mt19937 random(17);
  std::normal_distribution<float> noise(0.0f, 0.004f);
  for (LinearImage& run : noisyRuns)
    for (size_t i = 0; i < run.rgba.size(); ++i)
      if (i % 4 != 3) run.rgba[i] += noise(random);
  BenchReference noisy = gathered;
  gathered.setRuns(runs);
  noisy.setRuns(noisyRuns);
  ASSERT_GT(pixels.size(), size_t(width * height / 3));
  EXPECT_LT(gathered.noiseSteps(), 1e-3);
  EXPECT_GT(noisy.noiseSteps(), 0.5);

  gl::EglContext context;
  gl::MeshRenderer renderer;
  renderer.setMesh(mesh);
  for (Method method : {Method::Flat, Method::Gouraud, Method::CloughTocher}) {
    gl::RenderSettings render;
    render.method = method;
    renderer.render(camera, render, width, height);
    const RowValues row = truth.rowValues(renderer.readLinear());
    const RowError known = truth.error(row);
    for (const BenchReference* reference : {&gathered, &noisy}) {
      const RowError estimated = reference->error(row);
      std::printf("%-14s exact %.4g linear, %.4g steps; estimated %s linear, %s steps (noise %.3g steps)\n",
                  methodName(method).c_str(), known.linear.rms(), known.display.rms(),
                  (std::to_string(estimated.linear.rms()) + " [" + std::to_string(estimated.linear.rmsLow()) + ", " +
                   std::to_string(estimated.linear.rmsHigh()) + "]")
                      .c_str(),
                  (std::to_string(estimated.display.rms()) + " [" + std::to_string(estimated.display.rmsLow()) + ", " +
                   std::to_string(estimated.display.rmsHigh()) + "]")
                      .c_str(),
                  reference->noiseSteps());
      // The interval, widened by float's rounding of the images (it has no width without noise).
      auto covers = [](const ErrorEstimate& e, double value) {
        const double rounding = 1e-5 * value;
        return e.rmsLow() - rounding <= value && value <= e.rmsHigh() + rounding;
      };
      EXPECT_TRUE(covers(estimated.linear, known.linear.rms())) << methodName(method);
      EXPECT_TRUE(covers(estimated.display, known.display.rms())) << methodName(method);
    }
  }
}

}  // namespace
}  // namespace radview
