// The bench's yardstick: the squared error against a noisy reference, its noise taken out, and
// its interval; checked by simulation, where the reference's expectation is known.
#include "bench/error_estimate.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace radview {
namespace {

// Items whose reference expectation mu_i and noise sigma_i are drawn once; a row r_i = mu_i +
// d_i with a known error d_i; each trial draws K passes y_ik = mu_i + sigma_i z.
struct Simulation {
  std::vector<double> mu, sigma, row;
  double trueMeanSquare = 0.0;
  Simulation(size_t items, double error, double noise, uint64_t seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (size_t i = 0; i < items; ++i) {
      mu.push_back(uniform(random));
      // Noise and error uneven over the items, as over an image: a few items dominate.
      sigma.push_back(noise * (uniform(random) < 0.05 ? 8.0 : 1.0) * uniform(random));
      const double d = error * (uniform(random) < 0.05 ? 10.0 : 1.0) * (uniform(random) - 0.5);
      row.push_back(mu.back() + d);
      trueMeanSquare += d * d;
    }
    trueMeanSquare /= double(items);
  }
  // Normal passes, or (`skewed`) each pass the mean of 16 exponential draws: a run's mean of
  // Monte Carlo samples of a skewed integrand, not quite normal.
  std::vector<double> passes(int K, std::mt19937_64& random, bool skewed = false) const {
    std::normal_distribution<double> normal;
    std::exponential_distribution<double> exponential;
    std::vector<double> y(mu.size() * size_t(K));
    for (size_t i = 0; i < mu.size(); ++i)
      for (int k = 0; k < K; ++k) {
        double z = 0.0;
        if (skewed) {
          for (int j = 0; j < 16; ++j) z += exponential(random) - 1.0;
          z /= 4.0;  // 16 draws of variance 1: the mean's standard deviation 1/4, scaled to 1
        } else {
          z = normal(random);
        }
        y[i * size_t(K) + size_t(k)] = mu[i] + sigma[i] * z;
      }
    return y;
  }
};

TEST(ErrorEstimate, UnbiasedAndItsIntervalCoversTheTruthNineteenTimesInTwenty) {
  struct Case {
    int K;
    double error, noise;
    bool skewed;
  };
  // Noise below, about and above the error; normal and skewed passes.
  for (const Case c : {Case{4, 0.02, 0.05, false}, Case{8, 0.02, 0.05, false}, Case{4, 0.05, 0.01, false},
                       Case{4, 0.02, 0.02, true}, Case{16, 0.02, 0.05, true}}) {
    const int K = c.K;
    const Simulation simulation(2000, c.error, c.noise, 7);
    std::mt19937_64 random(11);
    const int trials = 400;
    int covered = 0;
    double meanEstimate = 0.0, meanNaive = 0.0, squares = 0.0;
    for (int t = 0; t < trials; ++t) {
      const std::vector<double> y = simulation.passes(K, random, c.skewed);
      const ErrorEstimate e = estimateMeanSquaredError(simulation.row, y, K);
      meanEstimate += e.meanSquare / trials;
      squares += e.meanSquare * e.meanSquare / trials;
      const double half = e.halfWidth();
      if (std::abs(e.meanSquare - simulation.trueMeanSquare) <= half) ++covered;
      // The naive figure: against the passes' mean, noise and all.
      double naive = 0.0;
      for (size_t i = 0; i < simulation.row.size(); ++i) {
        double m = 0.0;
        for (int k = 0; k < K; ++k) m += y[i * size_t(K) + size_t(k)] / K;
        naive += (simulation.row[i] - m) * (simulation.row[i] - m);
      }
      meanNaive += naive / double(simulation.row.size()) / trials;
    }
    const double coverage = double(covered) / trials;
    const double spread = std::sqrt(std::max(0.0, squares - meanEstimate * meanEstimate));
    std::printf(
        "K = %d, error %.2g, noise %.2g%s: true mean square %.4g, mean estimate %.4g (its own sd %.2g), naive %.4g; "
        "95 %% interval coverage %.3f\n",
        K, c.error, c.noise, c.skewed ? " (skewed)" : "", simulation.trueMeanSquare, meanEstimate,
        spread / std::sqrt(double(trials)), meanNaive, coverage);
    // The naive figure is biased up by the noise, the estimate is not (within four of its own
    // standard errors over the trials).
    EXPECT_GT(meanNaive, simulation.trueMeanSquare * (1.0 + 0.5 * c.noise * c.noise / (c.error * c.error) / K)) << K;
    EXPECT_NEAR(meanEstimate, simulation.trueMeanSquare, 4.0 * spread / std::sqrt(double(trials))) << K;
    EXPECT_GE(coverage, 0.90) << K;  // 400 trials: the binomial spread about 0.95 is 0.011
    EXPECT_LE(coverage, 0.98) << K;
  }
}

TEST(ErrorEstimate, ARowOnTheReferencesExpectationIsATieWithZero) {
  Simulation simulation(3000, 0.0, 0.05, 3);
  std::mt19937_64 random(5);
  const ErrorEstimate e = estimateMeanSquaredError(simulation.row, simulation.passes(4, random), 4);
  EXPECT_EQ(e.rmsLow(), 0.0);
  EXPECT_GT(e.rmsHigh(), 0.0);
  EXPECT_LT(std::abs(e.meanSquare), e.halfWidth());
}

TEST(ErrorEstimate, AgainstAnExactReferenceItIsThePlainMeanSquareWithNoInterval) {
  const ErrorEstimate e = estimateMeanSquaredError({1.0, 2.0, 3.0}, {1.0, 2.5, 2.0}, 1);
  EXPECT_DOUBLE_EQ(e.meanSquare, (0.25 + 1.0) / 3.0);
  EXPECT_EQ(e.standardError, 0.0);
  EXPECT_EQ(e.rmsLow(), e.rms());
  EXPECT_EQ(e.rmsHigh(), e.rms());
  EXPECT_EQ(meanNoiseVariance({1.0, 2.5, 2.0}, 1), 0.0);
}

// A reference exact at most items (a control variate that matches the scene there) and very
// noisy at a few: the unbiased variance can sum below zero, and the interval must not vanish.
TEST(ErrorEstimate, AFewNoisyItemsAmongExactOnesStillGiveAnInterval) {
  constexpr int K = 4;
  std::vector<double> row(1000, 1.0), passes(row.size() * K, 0.0);
  for (size_t i = 0; i < 5; ++i)
    for (int k = 0; k < K; ++k) passes[i * K + size_t(k)] = k % 2 ? 10.0 : -10.0;
  const ErrorEstimate e = estimateMeanSquaredError(row, passes, K);
  EXPECT_GT(e.standardError, 0.0);
  EXPECT_LT(e.rmsLow(), e.rms());
  EXPECT_GT(e.rmsHigh(), e.rms());
}

TEST(ErrorEstimate, NoiseVarianceIsTheVarianceOfThePassesMean) {
  // One item, passes 1, 2, 3, 6: sample variance 14 / 3, of the mean 14 / 12.
  EXPECT_DOUBLE_EQ(meanNoiseVariance({1.0, 2.0, 3.0, 6.0}, 4), 14.0 / 12.0);
}

TEST(ErrorEstimate, RefusesTwoPassesAndMismatchedSizes) {
  EXPECT_THROW(estimateMeanSquaredError({1.0}, {1.0, 2.0}, 2), Error);
  EXPECT_THROW(estimateMeanSquaredError({1.0, 2.0}, {1.0, 2.0, 3.0, 4.0}, 4), Error);
  EXPECT_THROW(estimateMeanSquaredError({1.0}, {1.0}, 0), Error);
}

TEST(ErrorEstimate, TiesAreOverlappingIntervals) {
  ErrorEstimate a, b;
  a.meanSquare = 1.0, a.standardError = 0.01, a.dof = 1e9;
  b.meanSquare = 1.1, b.standardError = 0.01, b.dof = 1e9;
  EXPECT_FALSE(tie(a, b));  // [0.99, 1.01] against [1.04, 1.06] in root mean square
  b.meanSquare = 1.03;
  EXPECT_TRUE(tie(a, b));
}

}  // namespace
}  // namespace radview
