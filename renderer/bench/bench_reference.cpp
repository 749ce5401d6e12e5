#include "bench/bench_reference.h"

#include "core/display_transform.h"
#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace radview {

namespace {

constexpr double kSteps = 255.0;                          // display units per 8-bit step
constexpr double kWeights[3] = {0.2126, 0.7152, 0.0722};  // luminance()'s

bool covered(const float* px) {
  return px[3] > 0.5f && std::isfinite(px[0]) && std::isfinite(px[1]) && std::isfinite(px[2]);
}

double linearLuminance(const float* px) { return covered(px) ? luminance(Rgb(px[0], px[1], px[2])) : 0.0; }

double displayLuminance(const float* px, double exposureScale) {
  return covered(px) ? kSteps * luminance(displayed(Rgb(px[0], px[1], px[2]), exposureScale)) : 0.0;
}

// d srgbEncode(v) / dv; 0 where the display clamps.
double srgbSlope(double v) {
  if (v < 0.0 || v >= 1.0) return 0.0;
  return v < 0.0031308 ? 12.92 : 1.055 / 2.4 * std::pow(v, 1.0 / 2.4 - 1.0);
}

std::vector<double> zeros(size_t n) { return std::vector<double>(n, 0.0); }

// The root mean square of row - the passes' mean, and the largest |row - mean|.
void againstMean(const std::vector<double>& row, const std::vector<double>& passes, int K, double& rms,
                 double& largest) {
  double sum = 0.0;
  largest = 0.0;
  for (size_t i = 0; i < row.size(); ++i) {
    double mean = 0.0;
    for (int k = 0; k < K; ++k) mean += passes[i * size_t(K) + size_t(k)];
    const double d = row[i] - mean / K;
    sum += d * d;
    largest = std::max(largest, std::abs(d));
  }
  rms = row.empty() ? 0.0 : std::sqrt(sum / double(row.size()));
}

}  // namespace

BenchReference::BenchReference(int width, int height, std::vector<uint32_t> pixels,
                               std::vector<std::array<uint32_t, 4>> smooth, std::vector<std::array<uint32_t, 4>> c0,
                               double exposureScale)
    : width_(width),
      height_(height),
      pixels_(std::move(pixels)),
      smooth_(std::move(smooth)),
      c0_(std::move(c0)),
      exposureScale_(exposureScale) {
  const size_t count = size_t(width) * size_t(height);
  for (uint32_t p : pixels_) RADVIEW_CHECK(p < count);
  for (const auto* stencils : {&smooth_, &c0_})
    for (const auto& s : *stencils)
      for (uint32_t p : s) RADVIEW_CHECK(p < count);
}

void BenchReference::setRuns(std::vector<LinearImage> runs) {
  if (runs.size() < 3)
    throw Error("bench reference: " + std::to_string(runs.size()) + " runs: the error estimate needs 3 or more");
  std::vector<const LinearImage*> pointers;
  for (const LinearImage& run : runs) pointers.push_back(&run);
  setFromRuns(pointers);
}

void BenchReference::setExact(const LinearImage& truth) {
  // A user's image says what is at every pixel, whatever its alpha (a path tracer's film may be
  // transparent where rays escape, and those pixels are not compared).
  LinearImage opaque = truth;
  for (size_t i = 3; i < opaque.rgba.size(); i += 4) opaque.rgba[i] = 1.0f;
  setFromRuns({&opaque});
}

void BenchReference::setFromRuns(const std::vector<const LinearImage*>& runs) {
  const int K = int(runs.size());
  const size_t count = size_t(width_) * size_t(height_);
  for (const LinearImage* run : runs)
    if (run->width != width_ || run->height != height_ || run->rgba.size() != count * 4)
      throw Error("bench reference: an image of " + std::to_string(run->width) + "x" + std::to_string(run->height) +
                  " for a bench of " + std::to_string(width_) + "x" + std::to_string(height_));

  mean_ = LinearImage{width_, height_, std::vector<float>(count * 4, 0.0f)};
  for (const LinearImage* run : runs)
    for (size_t i = 0; i < count * 4; ++i) mean_.rgba[i] += run->rgba[i] / float(K);

  // Every run's display value of every pixel, linearised about the mean (see the header).
  std::vector<double> display(count * size_t(K));
  for (size_t p = 0; p < count; ++p) {
    const float* m = &mean_.rgba[4 * p];
    const double shown = displayLuminance(m, exposureScale_);
    double slope[3] = {0.0, 0.0, 0.0};
    if (covered(m))
      for (int c = 0; c < 3; ++c)
        slope[c] = kSteps * kWeights[c] * exposureScale_ * srgbSlope(double(m[c]) * exposureScale_);
    for (int k = 0; k < K; ++k) {
      const float* y = &runs[size_t(k)]->rgba[4 * p];
      double v = shown;
      for (int c = 0; c < 3; ++c) v += slope[c] * (double(y[c]) - double(m[c]));
      display[p * size_t(K) + size_t(k)] = K == 1 ? shown : v;
    }
  }

  luminance_.assign(pixels_.size() * size_t(K), 0.0);
  display_.assign(pixels_.size() * size_t(K), 0.0);
  for (size_t i = 0; i < pixels_.size(); ++i)
    for (int k = 0; k < K; ++k) {
      const float* y = &runs[size_t(k)]->rgba[4 * size_t(pixels_[i])];
      // A run that sees nothing where the rows see a surface cannot say what is there.
      if (K > 1 && !covered(y))
        throw Error("bench reference: run " + std::to_string(k) + " sees no surface at pixel " +
                    std::to_string(pixels_[i] % uint32_t(width_)) + ", " +
                    std::to_string(pixels_[i] / uint32_t(width_)));
      luminance_[i * size_t(K) + size_t(k)] = linearLuminance(y);
      display_[i * size_t(K) + size_t(k)] = display[size_t(pixels_[i]) * size_t(K) + size_t(k)];
    }
  K_ = K;
  smoothJumps_ = jumps(smooth_, display);
  c0Jumps_ = jumps(c0_, display);
}

// Values of K runs (or one row, K = 1) at every pixel -> each stencil's jump, per run.
std::vector<double> BenchReference::jumps(const std::vector<std::array<uint32_t, 4>>& stencils,
                                          const std::vector<double>& displayOfPixel) const {
  const size_t K = displayOfPixel.size() / (size_t(width_) * size_t(height_));
  std::vector<double> out(stencils.size() * K);
  for (size_t s = 0; s < stencils.size(); ++s)
    for (size_t k = 0; k < K; ++k) {
      auto d = [&](int j) { return displayOfPixel[size_t(stencils[s][size_t(j)]) * K + k]; };
      out[s * K + k] = (d(3) - d(2)) - (d(1) - d(0));
    }
  return out;
}

RowValues BenchReference::rowValues(const LinearImage& row) const {
  if (row.width != width_ || row.height != height_)
    throw Error("bench: a row's image is " + std::to_string(row.width) + "x" + std::to_string(row.height) +
                ", the bench's " + std::to_string(width_) + "x" + std::to_string(height_));
  RowValues values;
  std::vector<double> display(size_t(row.width) * size_t(row.height));
  for (size_t p = 0; p < display.size(); ++p) display[p] = displayLuminance(&row.rgba[4 * p], exposureScale_);
  for (uint32_t p : pixels_) {
    values.luminance.push_back(float(linearLuminance(&row.rgba[4 * size_t(p)])));
    values.display.push_back(float(display[p]));
  }
  for (double j : jumps(smooth_, display)) values.smoothJumps.push_back(float(j));
  for (double j : jumps(c0_, display)) values.c0Jumps.push_back(float(j));
  return values;
}

RowError BenchReference::error(const RowValues& row) const {
  RADVIEW_CHECK(K_ > 0 && row.luminance.size() == pixels_.size() && row.smoothJumps.size() == smooth_.size() &&
                row.c0Jumps.size() == c0_.size());
  auto wide = [](const std::vector<float>& v) { return std::vector<double>(v.begin(), v.end()); };
  const std::vector<double> luminance = wide(row.luminance), display = wide(row.display);
  RowError e;
  e.linear = estimateMeanSquaredError(luminance, luminance_, K_);
  e.display = estimateMeanSquaredError(display, display_, K_);
  e.smoothJumps = estimateMeanSquaredError(wide(row.smoothJumps), smoothJumps_, K_);
  e.c0Jumps = estimateMeanSquaredError(wide(row.c0Jumps), c0Jumps_, K_);
  againstMean(luminance, luminance_, K_, e.rmse, e.maxError);
  againstMean(display, display_, K_, e.displayRmse, e.displayMax);
  return e;
}

ErrorSplit BenchReference::split(const RowValues& row, const std::vector<RowValues>& fromNodes) const {
  if (int(fromNodes.size()) != K_ || K_ < 3)
    throw Error("bench: the error split needs the row drawn from each of the reference's " + std::to_string(K_) +
                " runs (it has " + std::to_string(fromNodes.size()) + "), and 3 runs or more");
  const size_t n = pixels_.size();
  std::vector<double> displayOfRow(row.display.begin(), row.display.end()), drawn(n * size_t(K_)),
      reconstruction(n * size_t(K_)), zeros(n, 0.0);
  for (size_t i = 0; i < n; ++i)
    for (int k = 0; k < K_; ++k) {
      const size_t at = i * size_t(K_) + size_t(k);
      drawn[at] = fromNodes[size_t(k)].display[i];
      // 0 - (y_k - drawn_k): run k's difference, drawn from nodes minus the reference image,
      // each run's nodes and pixels independent of the others'.
      reconstruction[at] = display_[at] - drawn[at];
    }
  ErrorSplit split;
  split.solution = estimateMeanSquaredError(displayOfRow, drawn, K_);
  split.reconstruction = estimateMeanSquaredError(zeros, reconstruction, K_);
  split.nodeNoiseSteps = std::sqrt(meanNoiseVariance(drawn, K_));
  return split;
}

ErrorEstimate BenchReference::ownJumps(bool c0) const {
  const std::vector<double>& passes = c0 ? c0Jumps_ : smoothJumps_;
  return estimateMeanSquaredError(zeros(passes.size() / size_t(std::max(K_, 1))), passes, K_);
}

double BenchReference::noiseLinear() const { return std::sqrt(meanNoiseVariance(luminance_, K_)); }
double BenchReference::noiseSteps() const { return std::sqrt(meanNoiseVariance(display_, K_)); }

std::vector<double> BenchReference::pixelNoiseSteps() const {
  std::vector<double> noise = noiseVariances(display_, K_);
  for (double& n : noise) n = std::sqrt(n);
  return noise;
}

}  // namespace radview
