#pragma once
// What `radview bench` measures each row against, and how: the reference image as the mean of
// K independent runs of an estimator (the final gather, C&W §9.3.1), whose spread says how
// noisy that mean is; or one exact image (a closed form, a path tracer's converged render).
// Rows are compared on a fixed set of pixels (those whose surface and four neighbours' lie in
// one plane: bench/image_error.h) and of Mach-band stencils (bench/mach_bands.h), and every
// comparison is an ErrorEstimate (bench/error_estimate.h): the error against what the
// reference converges to, with the reference's noise taken out and a 95 % interval.
//
// Display steps: a pixel's displayed luminance D (exposure, clamp, sRGB, Rec. 709 weights:
// core/display_transform.h) times 255. D is not linear, so a run's display value is taken as
// D(m) + grad D(m) . (y - m), m the runs' mean and y the run's RGB: the runs' spread carried
// to the display to first order. What that leaves out, D's curvature times the mean's
// variance, is a small fraction of a step once the noise is a fraction of a step.
#include "bench/error_estimate.h"
#include "core/image.h"

#include <array>
#include <cstdint>
#include <vector>

namespace radview {

// One row's values on the bench's pixels and stencils.
struct RowValues {
  std::vector<float> luminance;             // Y(B) of each pixel, linear; an uncovered pixel 0
  std::vector<float> display;               // D(B) of each pixel, 8-bit steps
  std::vector<float> smoothJumps, c0Jumps;  // each stencil's gradient jump, steps per pixel
};

// A row's error against the reference, as bench.csv reports it.
struct RowError {
  ErrorEstimate linear;                // luminance of B, linear
  ErrorEstimate display;               // displayed luminance, steps
  ErrorEstimate smoothJumps, c0Jumps;  // the gradient jumps across element edges, steps per pixel
  // Against the runs' mean, noise included, as the bench has always reported.
  double rmse = 0.0, maxError = 0.0, displayRmse = 0.0, displayMax = 0.0;
};

// A row's display error split in two (bench/nodal_reference.h), each against what the
// reference converges to, with 95 % intervals. The nodes' noise reaches every pixel an element
// covers, so those pixels are not quite independent, as the intervals take them to be:
// `nodeNoiseSteps` says how much of the noise that is, beside the reference image's own.
struct ErrorSplit {
  ErrorEstimate solution;        // the row against the same method drawing the reference's nodal values
  ErrorEstimate reconstruction;  // the method drawing the reference's nodal values, against the reference
  double nodeNoiseSteps = 0.0;   // RMS over the pixels of the drawn values' noise (their runs' mean)
};

class BenchReference {
 public:
  // `pixels`: the indices of the compared pixels; `smooth` and `c0`: the stencils across untagged
  // and C0 edges (four pixel indices each). `exposureScale` as the rows are shown.
  // The reference and the rows are width x height.
  BenchReference(int width, int height, std::vector<uint32_t> pixels, std::vector<std::array<uint32_t, 4>> smooth,
                 std::vector<std::array<uint32_t, 4>> c0, double exposureScale);

  // The reference: K >= 3 independent runs of one size, or one exact image. Throws Error
  // otherwise. A pixel compared must be covered in every run.
  void setRuns(std::vector<LinearImage> runs);
  void setExact(const LinearImage& truth);

  // A row's values from its linear render (the reference's size).
  RowValues rowValues(const LinearImage& row) const;
  RowError error(const RowValues& row) const;

  // `fromNodes[k]`: the row's method drawing the nodal reference's run k (one per run).
  ErrorSplit split(const RowValues& row, const std::vector<RowValues>& fromNodes) const;

  // The reference's own gradient jumps (their root mean square, noise taken out), the
  // measure of Mach bands and kinks that the rows' are compared with.
  ErrorEstimate ownJumps(bool c0) const;
  // The root mean square noise of the reference image (the runs' mean) over the compared
  // pixels: linear, and in display steps. 0 for an exact reference.
  double noiseLinear() const;
  double noiseSteps() const;
  // The same per compared pixel (pixels()' order), display steps.
  std::vector<double> pixelNoiseSteps() const;

  int runs() const { return K_; }  // 1 for an exact reference
  const LinearImage& mean() const { return mean_; }
  const std::vector<uint32_t>& pixels() const { return pixels_; }  // the compared ones
  size_t pixelCount() const { return pixels_.size(); }
  size_t stencilCount(bool c0) const { return (c0 ? c0_ : smooth_).size(); }

 private:
  void setFromRuns(const std::vector<const LinearImage*>& runs);
  std::vector<double> jumps(const std::vector<std::array<uint32_t, 4>>& stencils,
                            const std::vector<double>& displayOfPixel) const;

  int width_, height_;
  std::vector<uint32_t> pixels_;
  std::vector<std::array<uint32_t, 4>> smooth_, c0_;
  double exposureScale_;
  int K_ = 0;
  LinearImage mean_;
  // [item * K + k]: run k's value of each compared pixel and stencil.
  std::vector<double> luminance_, display_, smoothJumps_, c0Jumps_;
};

}  // namespace radview
