#pragma once
// A per-pixel Monte Carlo estimate that converges pass by pass: one sample per pixel per pass,
// on all cores, kept as sums per independent run so that their spread measures the image's
// noise (bench/error_estimate.h). The final gather (eq. 9.9 over a solution, final_gather.h) and
// the path tracer (the rendering equation itself, path_tracer.h) are two estimators of it.
#include "core/image.h"
#include "core/types.h"

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

namespace radview {

// One sample of one pixel: B at the surface seen, or nothing seen.
struct PixelSample {
  Rgb B{0.0};
  bool covered = false;
  uint32_t rays = 0;  // rays cast for it
};

class ProgressiveImage {
 public:
  virtual ~ProgressiveImage() = default;
  ProgressiveImage(const ProgressiveImage&) = delete;
  ProgressiveImage& operator=(const ProgressiveImage&) = delete;

  // Adds up to `passes` passes of one sample per pixel, on all cores, and returns how many were
  // added. When `cancel` becomes true the pass under way is dropped (the image keeps whole
  // passes only) and fewer are returned. One thread at a time may call the non-const members.
  int addPasses(int passes, const std::atomic<bool>* cancel = nullptr);

  int samplesPerPixel() const { return passes_; }
  uint64_t raysCast() const { return rays_; }
  int width() const { return width_; }
  int height() const { return height_; }
  int runs() const { return runs_; }

  // The mean so far: RGB the mean B over the samples that saw a surface (not premultiplied, as
  // the GL renderer's linear image), alpha the fraction of samples that saw one. Row 0 is the top.
  LinearImage image() const;
  // The same over the passes of one run (0 .. runs() - 1): pass p belongs to run p mod runs.
  LinearImage runImage(int run) const;
  // The passes each run has had: whole rounds when samplesPerPixel() is a multiple of runs.
  int passesOfRun(int run) const;

  // Sample number `pass` of pixel (x, y), exactly as addPasses takes it.
  PixelSample samplePixel(int x, int y, int pass) const;

 protected:
  // Throws Error, its message starting with `estimator`, for a size below 1x1 or runs outside
  // 1..kMaxGatherRuns.
  ProgressiveImage(const std::string& estimator, int width, int height, int runs);

  // The numbers every pixel's sample of pass `passOfRun` (of its run) shares, formed once per
  // pass: a GatherSequence point and what the estimator appends to it.
  virtual std::vector<uint32_t> passWords(uint32_t passOfRun) const = 0;
  // Sample number `pass` of pixel (x, y), from that pass's words. Thread-safe; it must not
  // depend on which thread takes it, so the image is the same for any thread count.
  virtual PixelSample sample(int x, int y, int pass, const std::vector<uint32_t>& words) const = 0;
  // Work shared by every pass, done before the first one (e.g. what each pixel's centre sees).
  virtual void prepare() {}

 private:
  int width_, height_, runs_;
  std::vector<double> sum_;  // per run, per pixel: sum of B over covered samples (RGB), covered count
  std::vector<PixelSample> pass_;
  bool prepared_ = false;
  int passes_ = 0;
  uint64_t rays_ = 0;
};

}  // namespace radview
