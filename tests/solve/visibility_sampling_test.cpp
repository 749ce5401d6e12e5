// Visibility sampled where it is uncertain (element_to_node.h's VisibilitySampling): a node that
// sees a shooter wholly, or not at all, is settled by one batch; one that sees it in part takes
// batches until its standard error meets the target; the pooled estimate stays unbiased, and
// the standard error it reports is the spread its estimates have.
#include "solve/element_to_node.h"

#include "trace/form_factor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace radview {
namespace {

constexpr int kBatch = 16;  // samples per batch (a 4 x 4 grid)

std::vector<Vec3> square(double x0, double x1, double y0, double y1, double z) {
  // Facing down (-z), towards the receivers on z = 0.
  return {{x0, y1, z}, {x1, y1, z}, {x1, y0, z}, {x0, y0, z}};
}

// A unit shooter at z = 1 over receivers on z = 0, and an occluder half way up whose edge runs
// obliquely (x + 0.37 y < 0.6 hidden), so that the shadow it casts of the shooter's sample grid
// cuts the grid's cells unevenly. A sample s is hidden from x where (x + s) / 2 is.
struct Shadowed {
  Scene scene;
  PatchSampler sampler{square(0, 1, 0, 1, 1), kBatch};
  Shadowed() {
    scene.materials = {{"grey", Rgb(0.5), Rgb(0.0)}};
    scene.polygons = {{square(0, 1, 0, 1, 1), 0}, {{{-4, -3, 0.5}, {-4, 3, 0.5}, {-0.51, 3, 0.5}, {1.71, -3, 0.5}}, 0}};
  }
};

double estimate(const Shadowed& s, const RayCaster& caster, const Vec3& x, uint64_t key,
                const VisibilitySampling& sampling, size_t& rays, double* error = nullptr) {
  std::vector<AreaSample> scratch;
  SampleStream stream = SampleStream::forKey(11, 0, key);
  return elementToNodeFormFactor({x, Vec3(0, 0, 1)}, s.sampler, stream, &caster, rays, scratch, sampling, error);
}

TEST(VisibilitySampling, OneBatchSettlesAShooterSeenWhollyOrNotAtAll) {
  Shadowed s;
  const RayCaster caster(s.scene);
  VisibilitySampling adaptive;
  adaptive.maxBatches = 16;
  adaptive.targetError = 1e-9;
  // Far to the +x side the occluder is out of the way; far to the -x side it covers the shooter.
  for (const Vec3 x : {Vec3(5.0, 0.5, 0.0), Vec3(-3.0, 0.5, 0.0)}) {
    size_t rays = 0;
    double error = -1.0;
    const double F = estimate(s, caster, x, 1, adaptive, rays, &error);
    EXPECT_EQ(rays, size_t(kBatch)) << x.x;
    EXPECT_EQ(error, 0.0) << x.x;
    if (x.x > 0) {
      EXPECT_DOUBLE_EQ(F, pointToPolygonFormFactor(x, Vec3(0, 0, 1), square(0, 1, 0, 1, 1)));
    } else {
      EXPECT_EQ(F, 0.0);
    }
  }
}

TEST(VisibilitySampling, APartlySeenShooterTakesBatchesUntilItsErrorIsMet) {
  Shadowed s;
  const RayCaster caster(s.scene);
  const Vec3 x(0.5, 0.5, 0.0);
  VisibilitySampling sampling;
  sampling.maxBatches = 16;
  sampling.minBatches = 4;
  sampling.targetError = 1e-9;  // never met: every batch is taken
  size_t rays = 0;
  double error = 0.0;
  estimate(s, caster, x, 1, sampling, rays, &error);
  EXPECT_EQ(rays, size_t(16 * kBatch));
  EXPECT_GT(error, 0.0);
  sampling.targetError = 0.5;  // met at once: the fewest batches
  rays = 0;
  estimate(s, caster, x, 1, sampling, rays);
  EXPECT_EQ(rays, size_t(4 * kBatch));
  // One batch at most: the single-batch estimator, to the bit.
  size_t raysOne = 0, raysPlain = 0;
  sampling.maxBatches = 1;
  std::vector<AreaSample> scratch;
  SampleStream stream = SampleStream::forKey(11, 0, 1);
  EXPECT_EQ(estimate(s, caster, x, 1, sampling, raysOne),
            elementToNodeFormFactor({x, Vec3(0, 0, 1)}, s.sampler, stream, &caster, raysPlain, scratch));
  EXPECT_EQ(raysOne, raysPlain);
}

// Over many streams at a penumbra point: the batches' pooled estimate is centred on the truth
// (4096 samples' estimate), its spread is what its reported standard error says, and sixteen
// batches spread about a quarter as much as one.
TEST(VisibilitySampling, PooledBatchesAreUnbiasedAndTheirErrorIsTheirSpread) {
  Shadowed s;
  const RayCaster caster(s.scene);
  const Vec3 x(0.5, 0.5, 0.0);
  size_t rays = 0;
  VisibilitySampling reference;
  reference.maxBatches = 256;
  reference.minBatches = 256;
  const double truth = estimate(s, caster, x, 999999, reference, rays);
  VisibilitySampling one, sixteen;
  sixteen.maxBatches = sixteen.minBatches = 16;
  const int trials = 400;
  double meanSixteen = 0.0, squaresOne = 0.0, squaresSixteen = 0.0, reported = 0.0;
  for (int t = 0; t < trials; ++t) {
    double error = 0.0;
    const double a = estimate(s, caster, x, uint64_t(t), one, rays);
    const double b = estimate(s, caster, x, uint64_t(t), sixteen, rays, &error);
    meanSixteen += b / trials;
    squaresOne += (a - truth) * (a - truth) / trials;
    squaresSixteen += (b - truth) * (b - truth) / trials;
    reported += error * error / trials;
  }
  const double spreadOne = std::sqrt(squaresOne), spreadSixteen = std::sqrt(squaresSixteen);
  std::printf("truth %.5f; spread of one batch %.2e, of sixteen %.2e (ratio %.3f); reported %.2e\n", truth, spreadOne,
              spreadSixteen, spreadSixteen / spreadOne, std::sqrt(reported));
  ASSERT_GT(spreadOne, 0.0);
  EXPECT_NEAR(meanSixteen, truth, 4.0 * spreadSixteen / std::sqrt(double(trials)) + 1e-4);
  EXPECT_GT(spreadSixteen / spreadOne, 0.15);
  EXPECT_LT(spreadSixteen / spreadOne, 0.4);
  EXPECT_GT(std::sqrt(reported) / spreadSixteen, 0.75);
  EXPECT_LT(std::sqrt(reported) / spreadSixteen, 1.33);
}

// One batch alone (maxBatches 1) reports its own samples' spread, as if they were independent:
// never below what one stratified batch spreads over streams, and not far above it.
TEST(VisibilitySampling, OneBatchReportsItsOwnSpreadErringHigh) {
  Shadowed s;
  const RayCaster caster(s.scene);
  const Vec3 x(0.5, 0.5, 0.0);
  size_t rays = 0;
  VisibilitySampling reference;
  reference.maxBatches = reference.minBatches = 256;
  const double truth = estimate(s, caster, x, 999999, reference, rays);
  const int trials = 400;
  double squares = 0.0, reported = 0.0;
  for (int t = 0; t < trials; ++t) {
    double error = -1.0;
    const double a = estimate(s, caster, x, uint64_t(t), VisibilitySampling{}, rays, &error);
    squares += (a - truth) * (a - truth) / trials;
    reported += error * error / trials;
  }
  std::printf("one batch: spread %.2e, reported %.2e\n", std::sqrt(squares), std::sqrt(reported));
  EXPECT_GT(std::sqrt(reported) / std::sqrt(squares), 0.9);
  EXPECT_LT(std::sqrt(reported) / std::sqrt(squares), 3.0);
}

}  // namespace
}  // namespace radview
