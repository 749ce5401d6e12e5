#include "bench/error_estimate.h"

#include "core/error.h"

#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace radview {

namespace {

// The two-sided 95 % quantile of Student's t with `dof` degrees of freedom (the normal's 1.96
// in the limit).
double quantile95(double dof) {
  if (!(dof > 0.0)) return 0.0;
  if (dof > 1e7) return 1.959963984540054;
  return boost::math::quantile(boost::math::students_t_distribution<double>(dof), 0.975);
}

}  // namespace

double ErrorEstimate::halfWidth() const { return quantile95(dof) * standardError; }
double ErrorEstimate::rms() const { return std::sqrt(std::max(0.0, meanSquare)); }
double ErrorEstimate::rmsLow() const { return std::sqrt(std::max(0.0, meanSquare - halfWidth())); }
double ErrorEstimate::rmsHigh() const { return std::sqrt(std::max(0.0, meanSquare + halfWidth())); }

ErrorEstimate estimateMeanSquaredError(const std::vector<double>& row, const std::vector<double>& passes, int K) {
  if (K < 1 || K == 2)
    throw Error("error estimate: " + std::to_string(K) + " reference passes: expected 1 (exact) or 3 or more");
  if (passes.size() != row.size() * size_t(K))
    throw Error("error estimate: " + std::to_string(passes.size()) + " pass values for " + std::to_string(row.size()) +
                " items of " + std::to_string(K) + " passes");
  ErrorEstimate estimate;
  estimate.items = row.size();
  if (row.empty()) return estimate;
  double sum = 0.0, variance = 0.0, conservativeVariance = 0.0, varianceSquares = 0.0;
  for (size_t i = 0; i < row.size(); ++i) {
    double s1 = 0.0, s2 = 0.0;
    for (int k = 0; k < K; ++k) {
      const double e = row[i] - passes[i * size_t(K) + size_t(k)];
      s1 += e;
      s2 += e * e;
    }
    if (K == 1) {
      sum += s2;
      continue;
    }
    // The U-statistic over pairs of passes (see the header).
    const double g = (s1 * s1 - s2) / (double(K) * (K - 1));
    sum += g;
    // Its variance, for passes of variance sigma^2 about mu (Hoeffding's formula for a
    // U-statistic of degree 2 with kernel e_j e_k):
    //   Var g = 4 d^2 sigma^2 / K + 2 sigma^4 / (K (K - 1)),   d = r - mu,
    // estimated without bias for normal passes (each run's mean of many samples is close to
    // normal): sigma^4 by s^4 (K - 1) / (K + 1), and d^2 sigma^2 by g s^2 + 2 sigma^4 / (K (K - 1)).
    const double s2Passes = (s2 - s1 * s1 / K) / (K - 1);  // sample variance of the passes
    const double sigma4 = s2Passes * s2Passes * (K - 1) / (K + 1);
    const double pairTerm = 2.0 * sigma4 / (double(K) * (K - 1));
    const double v = 4.0 / K * (g * s2Passes + pairTerm) + pairTerm;
    variance += v;
    // The same with g no lower than 0 (as d^2 is): where a few items carry all the noise (a
    // reference exact elsewhere), their negative g can sum the unbiased variance below zero,
    // and this conservative one stands in.
    conservativeVariance += 4.0 / K * (std::max(g, 0.0) * s2Passes + pairTerm) + pairTerm;
    varianceSquares += std::max(v, 0.0) * std::max(v, 0.0);
  }
  const double n = double(row.size());
  if (!(variance > 0.0)) variance = conservativeVariance;
  estimate.meanSquare = sum / n;
  estimate.standardError = std::sqrt(std::max(variance, 0.0)) / n;
  // Welch-Satterthwaite: each item's variance estimate has about K - 1 degrees of freedom.
  // A sum has no fewer than any one of its terms' K - 1 (the clipped terms above can say less).
  estimate.dof = variance > 0.0 ? std::max(double(K - 1), variance * variance / (varianceSquares / (K - 1))) : 0.0;
  return estimate;
}

std::vector<double> noiseVariances(const std::vector<double>& passes, int K) {
  if (K < 2 || passes.empty()) return std::vector<double>(K < 1 ? 0 : passes.size() / size_t(K), 0.0);
  const size_t items = passes.size() / size_t(K);
  std::vector<double> variances(items);
  for (size_t i = 0; i < items; ++i) {
    double mean = 0.0, squares = 0.0;
    for (int k = 0; k < K; ++k) mean += passes[i * size_t(K) + size_t(k)];
    mean /= K;
    for (int k = 0; k < K; ++k) {
      const double d = passes[i * size_t(K) + size_t(k)] - mean;
      squares += d * d;
    }
    variances[i] = squares / (K - 1) / K;
  }
  return variances;
}

double meanNoiseVariance(const std::vector<double>& passes, int K) {
  const std::vector<double> variances = noiseVariances(passes, K);
  double sum = 0.0;
  for (double v : variances) sum += v;
  return variances.empty() ? 0.0 : sum / double(variances.size());
}

bool tie(const ErrorEstimate& a, const ErrorEstimate& b) {
  return a.rmsLow() <= b.rmsHigh() && b.rmsLow() <= a.rmsHigh();
}

}  // namespace radview
