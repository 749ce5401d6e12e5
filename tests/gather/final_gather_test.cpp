#include "gather/final_gather.h"

#include "core/error.h"
#include "gather_scenes.h"
#include "tests/solve/solver_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace radview {
namespace {

// Looks at the receiver obliquely from below the emitter's height, so that most pixels see
// the receiver and some the emitter's face.
GatherSettings receiverView(int width, int height) {
  GatherSettings settings;
  settings.width = width;
  settings.height = height;
  settings.camera = test::receiverCamera();
  return settings;
}

TEST(FinalGatherTest, ReceiverUnderASquareEmitterConvergesToTheExactFormFactorFasterThanMonteCarlo) {
  const RadiosityMesh mesh = test::receiverUnderSquareEmitterMesh();
  const GatherSettings settings = receiverView(64, 64);
  const std::vector<double> expected = test::expectedReceiverRadiosity(settings.camera, settings.width, settings.height);
  FinalGather gather(mesh, settings);
  std::vector<test::ErrorFigures> figures;
  for (int spp : {1, 4, 16, 64}) {
    gather.addPasses(spp - gather.samplesPerPixel());
    ASSERT_EQ(gather.samplesPerPixel(), spp);
    figures.push_back(test::errorAgainst(gather.image(), expected));
    const test::ErrorFigures& f = figures.back();
    std::printf(
        "receiver under a square emitter, %2d spp: RMSE %.5f (%.2f%% of the mean %.5f), mean error %+.6f, "
        "%zu pixels\n",
        spp, f.rmse, 100.0 * f.rmse / f.meanExpected, f.meanExpected, f.meanSigned, f.pixels);
  }
  ASSERT_GT(figures[0].pixels, 1000u);  // a third of the image is receiver, fully
  // Independent samples' error falls as N^-1/2, a factor 2 per 4x samples; the stratified
  // passes (gather_sequence.h) must do at least that at each step (a bias floor, or samples
  // reused between passes, fails it), and over the whole range do 4x better than it: the
  // direct light of an unoccluded emitter is smooth, where the rate approaches N^-1.
  for (int k = 1; k < 4; ++k) EXPECT_LT(figures[size_t(k)].rmse, 0.5 * figures[size_t(k) - 1].rmse) << k;
  EXPECT_LT(figures[3].rmse, 0.25 * figures[0].rmse / 8.0);
  // Unbiased: the mean error over the pixels is within 4 standard errors of 0 (and a wrong pdf,
  // e.g. a missing 1/pi, is off by far more than that).
  const test::ErrorFigures& last = figures.back();
  EXPECT_LT(std::abs(last.meanSigned), 4.0 * last.rmse / std::sqrt(double(last.pixels)));
  EXPECT_LT(std::abs(last.meanSigned), 0.002 * last.meanExpected);
}

TEST(FinalGatherTest, FurnaceGivesEOverOneMinusRho) {
  // A closed box, every surface rho 0.5 and E 1, B^ = E / (1 - rho) = 2 everywhere. The
  // gather's direct part sees E over the whole hemisphere (F sums to 1) and its indirect part
  // B^ - E = 1 in every direction: E + rho (E + rho E / (1 - rho)) = E / (1 - rho).
  const Rgb rho(0.5, 0.25, 0.75), E(1.0, 2.0, 0.5);
  const Rgb exact = E / (Rgb(1.0) - rho);
  RadiosityMesh mesh = meshUniformly(test::furnaceBox(rho, E), 0.25);
  for (Node& node : mesh.nodes) node.B = exact;
  for (Method method : {Method::Flat, Method::Gouraud, Method::CloughTocher}) {
    GatherSettings settings;
    settings.interpolant = method;
    settings.width = settings.height = 48;
    settings.camera = test::furnaceCamera();
    FinalGather gather(mesh, settings);
    gather.addPasses(32);
    const LinearImage image = gather.image();
    Rgb mean(0.0);
    std::vector<double> errors;  // relative, per pixel, the largest channel
    const size_t pixels = size_t(settings.width) * size_t(settings.height);
    for (size_t i = 0; i < pixels; ++i) {
      ASSERT_EQ(image.rgba[4 * i + 3], 1.0f) << "pixel " << i << " sees no surface inside the closed box";
      const Rgb B(image.rgba[4 * i], image.rgba[4 * i + 1], image.rgba[4 * i + 2]);
      mean += B / double(pixels);
      const Rgb relative = glm::abs(B - exact) / exact;
      errors.push_back(std::max({relative.r, relative.g, relative.b}));
    }
    // Pixels next to the box's edges see the adjacent wall's emission at r -> 0: area sampling
    // has unbounded variance there, so the spread is judged by quantiles, not an RMSE.
    std::sort(errors.begin(), errors.end());
    const double median = errors[errors.size() / 2], p90 = errors[errors.size() * 9 / 10];
    std::printf(
        "furnace, %s B^, 32 spp: mean %.5f %.5f %.5f (exact %.5f %.5f %.5f), relative error median %.2f%%, "
        "90th percentile %.2f%%\n",
        methodName(method).c_str(), mean.r, mean.g, mean.b, exact.r, exact.g, exact.b, 100.0 * median, 100.0 * p90);
    // The standard error of the mean is the RMSE / 48, about 0.2%: 1% is 5 of them.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], exact[c], 0.01 * exact[c]) << methodName(method);
    EXPECT_LT(median, 0.08) << methodName(method);
    EXPECT_LT(p90, 0.2) << methodName(method);
  }
}

TEST(FinalGatherTest, SameSeedGivesTheSameImageBitForBitWhateverTheThreads) {
  const RadiosityMesh mesh = test::receiverUnderSquareEmitterMesh();
  GatherSettings settings = receiverView(40, 30);
  settings.seed = 7;
  settings.emitterSamples = 2;
  FinalGather a(mesh, settings), b(mesh, settings);
  a.addPasses(3);
  b.addPasses(1);
  b.addPasses(2);
  const LinearImage imageA = a.image(), imageB = b.image();
  ASSERT_EQ(imageA.rgba.size(), imageB.rgba.size());
  EXPECT_EQ(std::memcmp(imageA.rgba.data(), imageB.rgba.data(), imageA.rgba.size() * sizeof(float)), 0);
  EXPECT_EQ(a.raysCast(), b.raysCast());

  // One thread: every sample taken in order on this thread, summed as a pass sums them.
  std::vector<double> sum(size_t(settings.width) * size_t(settings.height) * 4, 0.0);
  for (int pass = 0; pass < 3; ++pass)
    for (int y = 0; y < settings.height; ++y)
      for (int x = 0; x < settings.width; ++x) {
        const PixelSample s = a.samplePixel(x, y, pass);
        if (!s.covered) continue;
        const size_t i = size_t(y) * size_t(settings.width) + size_t(x);
        for (int c = 0; c < 3; ++c) sum[4 * i + size_t(c)] += s.B[c];
        sum[4 * i + 3] += 1.0;
      }
  size_t mismatches = 0;
  for (size_t i = 0; i < sum.size() / 4; ++i) {
    for (int c = 0; c < 3; ++c)
      if (sum[4 * i + 3] > 0 && imageA.rgba[4 * i + size_t(c)] != float(sum[4 * i + size_t(c)] / sum[4 * i + 3]))
        ++mismatches;
    if (imageA.rgba[4 * i + 3] != float(sum[4 * i + 3] / 3.0)) ++mismatches;
  }
  EXPECT_EQ(mismatches, 0u);

  settings.seed = 8;
  FinalGather c(mesh, settings);
  c.addPasses(3);
  EXPECT_NE(std::memcmp(imageA.rgba.data(), c.image().rgba.data(), imageA.rgba.size() * sizeof(float)), 0);
}

TEST(FinalGatherTest, CancelledPassIsDropped) {
  const RadiosityMesh mesh = test::receiverUnderSquareEmitterMesh();
  FinalGather gather(mesh, receiverView(16, 16));
  std::atomic<bool> cancel{true};
  EXPECT_EQ(gather.addPasses(4, &cancel), 0);
  EXPECT_EQ(gather.samplesPerPixel(), 0);
  cancel = false;
  EXPECT_EQ(gather.addPasses(2, &cancel), 2);
  EXPECT_EQ(gather.samplesPerPixel(), 2);
}

TEST(FinalGatherTest, BackFacesShowTheInterpolatedSolutionAsTheGlRendererDoes) {
  // From above, the emitter's back face hides the receiver's centre: it shows B^ = E there.
  const RadiosityMesh mesh = test::receiverUnderSquareEmitterMesh();
  GatherSettings settings;
  settings.width = settings.height = 9;
  settings.camera = test::emitterBackCamera();
  FinalGather gather(mesh, settings);
  gather.addPasses(2);
  const LinearImage image = gather.image();
  for (size_t i = 0; i < 81; ++i) {
    EXPECT_EQ(image.rgba[4 * i], 1.0f) << i;
    EXPECT_EQ(image.rgba[4 * i + 3], 1.0f) << i;
  }
}

TEST(FinalGatherTest, RejectsBadSettings) {
  const RadiosityMesh mesh = test::receiverUnderSquareEmitterMesh();
  GatherSettings settings = receiverView(0, 10);
  EXPECT_THROW(FinalGather(mesh, settings), Error);
  settings = receiverView(10, 10);
  settings.emitterSamples = 0;
  EXPECT_THROW(FinalGather(mesh, settings), Error);
}

}  // namespace
}  // namespace radview
