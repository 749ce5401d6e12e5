#pragma once
// How far a row is from what its reference converges to, when the reference is noisy: the
// yardstick of `radview bench`. The reference comes as K independent estimates of the same
// image (its passes: the final gather's independent runs, each with its own sample
// sequences). For an item i (a pixel, or a stencil of pixels) with the row's value r_i and the
// passes' values y_i1 .. y_iK of mean m_i and sample variance s_i^2,
//     g_i = (r_i - m_i)^2 - s_i^2 / K  =  sum over j != k of (r_i - y_ij)(r_i - y_ik) / (K (K - 1))
// has expectation (r_i - mu_i)^2, mu_i the reference's expectation: the squared error with the
// reference's noise taken out. Its mean over the items estimates the row's mean squared error
// without bias, however noisy the reference.
//
// The interval: the only random thing in the measurement is the reference's sampling (the row
// is a deterministic render, and the items compared are all of them, not a sample of some
// larger set). Items are independent (every pixel draws its own sample sequence), so the
// estimate's variance is the sum of the items' variances, each estimated from its K passes by
// the U-statistic's variance formula (unbiased for normal passes; made conservative where the
// sum comes out below zero; the jackknife, which needs
// no such assumption, is far too wide at K = 4 where the noise is larger than the error); the
// interval is Student's t with Welch-Satterthwaite's effective degrees of freedom, which are
// about the item count when no few items dominate, and fall towards K - 1 when they do.
// Resampling blocks of pixels instead would measure how the error varies across the image,
// not how uncertain the figure is.
#include <cstddef>
#include <vector>

namespace radview {

struct ErrorEstimate {
  double meanSquare = 0.0;     // unbiased estimate of the mean over items of (r - mu)^2; may be < 0
  double standardError = 0.0;  // of meanSquare (0 against an exact reference)
  double dof = 0.0;            // effective degrees of freedom of standardError (0 when it is 0)
  size_t items = 0;

  // sqrt(max(0, meanSquare)) and the 95 % interval's ends, mapped through the same root.
  double rms() const;
  double rmsLow() const;
  double rmsHigh() const;
  // The 95 % interval's half-width for meanSquare.
  double halfWidth() const;
};

// `row[i]` the row's value of item i; `passes[i * K + k]` pass k's value of it. K >= 3 gives
// an interval; K = 1 is an exact reference: the plain mean squared error, no interval. Throws
// Error for K = 2 (too few to estimate the variance's own spread) or sizes that do not match.
ErrorEstimate estimateMeanSquaredError(const std::vector<double>& row, const std::vector<double>& passes, int K);

// The variance of the passes' mean, s_i^2 / K, of each item (0 for K = 1), and its average
// over the items: the reference's own mean squared noise.
std::vector<double> noiseVariances(const std::vector<double>& passes, int K);
double meanNoiseVariance(const std::vector<double>& passes, int K);

// Whether two estimates' 95 % intervals for the root mean square overlap: a tie.
bool tie(const ErrorEstimate& a, const ErrorEstimate& b);

}  // namespace radview
