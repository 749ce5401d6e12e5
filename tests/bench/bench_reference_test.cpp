// What the bench measures rows against: runs of a noisy reference or an exact image
// (renderer/bench/bench_reference.h).
#include "bench/bench_reference.h"

#include "core/display_transform.h"
#include "core/error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace radview {
namespace {

constexpr int kSide = 8;

LinearImage grey(double value) {
  LinearImage image{kSide, kSide, std::vector<float>(kSide * kSide * 4, 1.0f)};
  for (size_t i = 0; i < image.rgba.size(); ++i)
    if (i % 4 != 3) image.rgba[i] = float(value);
  return image;
}

BenchReference everyPixel() {
  std::vector<uint32_t> pixels;
  for (uint32_t p = 0; p < kSide * kSide; ++p) pixels.push_back(p);
  // One stencil along the first row, across a (pretend) edge between pixels 1 and 2.
  return BenchReference(kSide, kSide, pixels, {{0, 1, 2, 3}}, {}, 1.0);
}

TEST(BenchReference, RunsNoiseIsTakenOutOfTheSquaredError) {
  // Runs +s, -s, +s, -s about 0.25: their mean is 0.25 exactly, their sample variance 4 s^2 / 3,
  // so the mean's noise variance is s^2 / 3, and a row 0.1 above reads 0.1^2 - s^2 / 3.
  const double s = 0.02;
  std::vector<LinearImage> runs;
  for (int k = 0; k < 4; ++k) runs.push_back(grey(0.25 + (k % 2 ? -s : s)));
  BenchReference reference = everyPixel();
  reference.setRuns(runs);
  EXPECT_EQ(reference.runs(), 4);
  EXPECT_NEAR(reference.mean().rgba[0], 0.25, 1e-7);
  EXPECT_NEAR(reference.noiseLinear(), s / std::sqrt(3.0), 1e-6);
  const RowError e = reference.error(reference.rowValues(grey(0.35)));
  EXPECT_NEAR(e.linear.meanSquare, 0.01 - s * s / 3.0, 1e-6);
  EXPECT_NEAR(e.rmse, 0.1, 1e-6) << "against the runs' mean as it is";
  // In display steps, to first order: the slope of 255 sRGB at 0.25 times the linear figures.
  const double slope = 255.0 * (srgbEncode(0.2501) - srgbEncode(0.2499)) / 0.0002;
  EXPECT_NEAR(reference.noiseSteps(), slope * s / std::sqrt(3.0), 1e-3 * slope * s);
  EXPECT_NEAR(e.displayRmse, 255.0 * (srgbEncode(0.35) - srgbEncode(0.25)), 1e-3);
  // A flat row and a flat reference: no gradient jump in either.
  EXPECT_NEAR(e.smoothJumps.meanSquare, 0.0, 1e-9);
}

TEST(BenchReference, AnExactReferenceGivesExactErrorsWithNoInterval) {
  BenchReference reference = everyPixel();
  LinearImage truth = grey(0.5);
  truth.rgba[3] = 0.0f;  // a path tracer's transparent film: its value still counts
  reference.setExact(truth);
  EXPECT_EQ(reference.runs(), 1);
  EXPECT_EQ(reference.noiseLinear(), 0.0);
  const RowError e = reference.error(reference.rowValues(grey(0.4)));
  EXPECT_NEAR(e.linear.rms(), 0.1, 1e-6);
  EXPECT_EQ(e.linear.standardError, 0.0);
  EXPECT_NEAR(e.display.rms(), 255.0 * (srgbEncode(0.5) - srgbEncode(0.4)), 1e-3);
}

TEST(BenchReference, RefusesTooFewRunsAndImagesOfAnotherSize) {
  BenchReference reference = everyPixel();
  EXPECT_THROW(reference.setRuns({grey(0.1), grey(0.2)}), Error);
  LinearImage small{2, 2, std::vector<float>(16, 1.0f)};
  EXPECT_THROW(reference.setRuns({small, small, small, small}), Error);
  EXPECT_THROW(reference.setExact(small), Error);
  EXPECT_THROW(reference.rowValues(small), Error);
}

}  // namespace
}  // namespace radview
