#include "gather/path_tracer.h"

#include "core/error.h"
#include "gather_scenes.h"
#include "tests/solve/solver_scenes.h"
#include "trace/form_factor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace radview {
namespace {

// The receiver seen obliquely from below the emitter's height, as the final gather's test does.
PathTraceSettings receiverView(int width, int height) {
  PathTraceSettings settings;
  settings.width = width;
  settings.height = height;
  settings.camera = test::receiverCamera();
  return settings;
}

TEST(PathTracerTest, ReceiverUnderASquareEmitterConvergesToLambertsFormula) {
  // One bounce and no occlusion: B = rho E F(x -> emitter) on the receiver. The light the
  // receiver sends back meets the emitter, which reflects nothing, so every longer path adds 0.
  const Scene scene = test::receiverUnderSquareEmitter();
  const PathTraceSettings settings = receiverView(64, 64);
  const std::vector<double> expected =
      test::expectedReceiverRadiosity(settings.camera, settings.width, settings.height);
  PathTracer tracer(scene, settings);
  std::vector<test::ErrorFigures> figures;
  for (int spp : {1, 4, 16, 64}) {
    tracer.addPasses(spp - tracer.samplesPerPixel());
    figures.push_back(test::errorAgainst(tracer.image(), expected));
    const test::ErrorFigures& f = figures.back();
    std::printf(
        "path tracer, receiver under a square emitter, %2d spp: RMSE %.5f (%.2f%% of the mean %.5f), mean error "
        "%+.6f\n",
        spp, f.rmse, 100.0 * f.rmse / f.meanExpected, f.meanExpected, f.meanSigned);
  }
  ASSERT_GT(figures[0].pixels, 1000u);
  // At least independent samples' N^-1/2 at each step (a bias floor fails it).
  for (int k = 1; k < 4; ++k) EXPECT_LT(figures[size_t(k)].rmse, 0.5 * figures[size_t(k) - 1].rmse) << k;
  // Unbiased: the mean error within 4 standard errors of 0; a wrong MIS weight or pdf (weights
  // that do not sum to 1, a missing 1/pi) is off by far more.
  const test::ErrorFigures& last = figures.back();
  EXPECT_LT(std::abs(last.meanSigned), 4.0 * last.rmse / std::sqrt(double(last.pixels)));
  EXPECT_LT(std::abs(last.meanSigned), 0.002 * last.meanExpected);
}

TEST(PathTracerTest, PointEstimateConvergesToLambertsFormula) {
  const Scene scene = test::receiverUnderSquareEmitter();
  const PathTracer tracer(scene, receiverView(4, 4));
  for (const Vec3& x : {Vec3(0.0, 0.0, 0.0), Vec3(0.7, -0.3, 0.0), Vec3(1.9, 1.9, 0.0)}) {
    const double exact = 0.5 * pointToPolygonFormFactor(x, {0, 0, 1}, scene.polygons[1].vertices);
    const int n = 4096;
    double sum = 0.0, squares = 0.0;
    for (int pass = 0; pass < n; ++pass) {
      const double B = tracer.samplePoint(scene.materials[0], {0, 0, 1}, x, 3, pass).r;
      sum += B;
      squares += B * B;
    }
    const double mean = sum / n, standardError = std::sqrt(std::max(0.0, squares / n - mean * mean) / n);
    std::printf("path tracer at (%.1f, %.1f): %.6f +- %.6f, exact %.6f\n", x.x, x.y, mean, standardError, exact);
    // Stratified passes beat the independent samples' standard error, so it bounds the error.
    EXPECT_NEAR(mean, exact, 4.0 * standardError + 1e-9);
  }
}

TEST(PathTracerTest, FurnaceGivesEOverOneMinusRhoByPathsOfEveryLength) {
  // A closed box, every surface rho and E: B = E / (1 - rho) in every channel, the sum over
  // paths of every length (rho^k E): Russian roulette must end paths without losing any.
  const Rgb rho(0.5, 0.25, 0.75), E(1.0, 2.0, 0.5);
  const Rgb exact = E / (Rgb(1.0) - rho);
  const Scene scene = test::furnaceBox(rho, E);
  PathTraceSettings settings;
  settings.width = settings.height = 48;
  settings.camera = test::furnaceCamera();
  PathTracer tracer(scene, settings);
  tracer.addPasses(32);
  const LinearImage image = tracer.image();
  const size_t pixels = size_t(settings.width) * size_t(settings.height);
  Rgb mean(0.0), squares(0.0);
  for (size_t i = 0; i < pixels; ++i) {
    ASSERT_EQ(image.rgba[4 * i + 3], 1.0f) << "pixel " << i << " sees no surface inside the closed box";
    const Rgb B(image.rgba[4 * i], image.rgba[4 * i + 1], image.rgba[4 * i + 2]);
    mean += B / double(pixels);
    squares += B * B / double(pixels);
  }
  for (int c = 0; c < 3; ++c) {
    const double standardError = std::sqrt(std::max(0.0, squares[c] - mean[c] * mean[c]) / double(pixels));
    std::printf("furnace, channel %d: %.5f +- %.5f, exact %.5f\n", c, mean[c], standardError, exact[c]);
    EXPECT_NEAR(mean[c], exact[c], 4.0 * standardError + 1e-6) << c;
    EXPECT_NEAR(mean[c], exact[c], 0.01 * exact[c]) << c;
  }
}

TEST(PathTracerTest, SameSeedGivesTheSameImageWhateverThePassesAndThreads) {
  const Scene scene = test::closedCornellBox();
  PathTraceSettings settings;
  settings.width = 24;
  settings.height = 20;
  settings.camera.eye = {278, 273, -800};
  settings.camera.target = {278, 273, 0};
  settings.camera.yfov = glm::radians(39.0);
  settings.seed = 5;
  settings.runs = 2;
  PathTracer a(scene, settings), b(scene, settings);
  a.addPasses(4);
  b.addPasses(1);
  b.addPasses(3);
  const LinearImage imageA = a.image(), imageB = b.image();
  EXPECT_EQ(std::memcmp(imageA.rgba.data(), imageB.rgba.data(), imageA.rgba.size() * sizeof(float)), 0);
  EXPECT_EQ(a.raysCast(), b.raysCast());
  // Sample by sample on this thread, as the passes take them.
  for (int pass = 0; pass < 4; ++pass)
    for (int y = 0; y < settings.height; y += 7)
      for (int x = 0; x < settings.width; x += 5) {
        const PixelSample s = a.samplePixel(x, y, pass);
        const PixelSample t = a.samplePixel(x, y, pass);
        EXPECT_EQ(s.B, t.B);
      }
  EXPECT_EQ(a.passesOfRun(0), 2);
  EXPECT_EQ(a.passesOfRun(1), 2);
  settings.seed = 6;
  PathTracer c(scene, settings);
  c.addPasses(4);
  EXPECT_NE(std::memcmp(imageA.rgba.data(), c.image().rgba.data(), imageA.rgba.size() * sizeof(float)), 0);
}

TEST(PathTracerTest, BackFacesAreBlack) {
  // From above, the emitter's back hides the receiver's centre: surfaces are one-sided, so its
  // back neither emits nor reflects.
  const Scene scene = test::receiverUnderSquareEmitter();
  PathTraceSettings settings;
  settings.width = settings.height = 9;
  settings.camera = test::emitterBackCamera();
  PathTracer tracer(scene, settings);
  tracer.addPasses(2);
  const LinearImage image = tracer.image();
  for (size_t i = 0; i < 81; ++i) {
    EXPECT_EQ(image.rgba[4 * i], 0.0f) << i;
    EXPECT_EQ(image.rgba[4 * i + 3], 1.0f) << i;
  }
}

TEST(PathTracerTest, RejectsBadSettings) {
  const Scene scene = test::receiverUnderSquareEmitter();
  EXPECT_THROW(PathTracer(scene, receiverView(0, 10)), Error);
  PathTraceSettings settings = receiverView(10, 10);
  settings.runs = 0;
  EXPECT_THROW(PathTracer(scene, settings), Error);
}

}  // namespace
}  // namespace radview
