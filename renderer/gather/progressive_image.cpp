#include "gather/progressive_image.h"

#include "core/error.h"
#include "core/limits.h"
#include "core/parallel_for.h"

namespace radview {

namespace {

int checkedSize(const std::string& estimator, int width, int height) {
  if (width < 1 || height < 1)
    throw Error(estimator + ": the image size " + std::to_string(width) + "x" + std::to_string(height) +
                " is empty");
  return width;
}

int checkedRuns(const std::string& estimator, int runs) {
  if (runs < 1 || runs > kMaxGatherRuns)
    throw Error(estimator + ": " + std::to_string(runs) + " runs: expected 1 to " + std::to_string(kMaxGatherRuns));
  return runs;
}

// The mean of `runs` runs' sums (ProgressiveImage's sum_) over `passes` passes in all.
LinearImage meanOfRuns(const double* sums, int runs, size_t pixels, int passes, int width, int height) {
  LinearImage image{width, height, std::vector<float>(pixels * 4, 0.0f)};
  if (passes == 0) return image;
  for (size_t i = 0; i < pixels; ++i) {
    double total[4] = {0.0, 0.0, 0.0, 0.0};
    for (int r = 0; r < runs; ++r)
      for (int c = 0; c < 4; ++c) total[c] += sums[(size_t(r) * pixels + i) * 4 + size_t(c)];
    if (total[3] == 0.0) continue;
    for (int c = 0; c < 3; ++c) image.rgba[4 * i + size_t(c)] = float(total[c] / total[3]);
    image.rgba[4 * i + 3] = float(total[3] / passes);
  }
  return image;
}

}  // namespace

ProgressiveImage::ProgressiveImage(const std::string& estimator, int width, int height, int runs)
    : width_(checkedSize(estimator, width, height)),
      height_(height),
      runs_(checkedRuns(estimator, runs)),
      sum_(size_t(runs) * size_t(width) * size_t(height) * 4, 0.0),
      pass_(size_t(width) * size_t(height)) {}

PixelSample ProgressiveImage::samplePixel(int x, int y, int pass) const {
  return sample(x, y, pass, passWords(uint32_t(pass / runs_)));
}

int ProgressiveImage::addPasses(int passes, const std::atomic<bool>* cancel) {
  auto cancelled = [&] { return cancel && cancel->load(std::memory_order_relaxed); };
  if (passes > 0 && !prepared_) {
    prepare();
    prepared_ = true;
  }
  for (int p = 0; p < passes; ++p) {
    const std::vector<uint32_t> words = passWords(uint32_t(passes_ / runs_));
    double* sum = &sum_[size_t(passes_ % runs_) * pass_.size() * 4];
    parallelFor(
        size_t(height_),
        [&](size_t y) {
          if (cancelled()) return;
          for (int x = 0; x < width_; ++x) pass_[y * size_t(width_) + size_t(x)] = sample(x, int(y), passes_, words);
        },
        1);
    if (cancelled()) return p;
    // Added in pixel order after the pass, so the sums do not depend on the threads either.
    for (size_t i = 0; i < pass_.size(); ++i) {
      if (pass_[i].covered) {
        sum[4 * i + 0] += pass_[i].B.r;
        sum[4 * i + 1] += pass_[i].B.g;
        sum[4 * i + 2] += pass_[i].B.b;
        sum[4 * i + 3] += 1.0;
      }
      rays_ += pass_[i].rays;
    }
    ++passes_;
  }
  return passes;
}

int ProgressiveImage::passesOfRun(int run) const { return passes_ / runs_ + (run < passes_ % runs_ ? 1 : 0); }

LinearImage ProgressiveImage::image() const {
  return meanOfRuns(sum_.data(), runs_, pass_.size(), passes_, width_, height_);
}

LinearImage ProgressiveImage::runImage(int run) const {
  RADVIEW_CHECK(run >= 0 && run < runs_);
  return meanOfRuns(&sum_[size_t(run) * pass_.size() * 4], 1, pass_.size(), passesOfRun(run), width_, height_);
}

}  // namespace radview
