#include "app/bench_reference_run.h"

#include "core/limits.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

namespace radview {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// One line on standard error, rewritten in place at most twice a second: a bar, what is done,
// and the time left.
void showProgress(double fraction, const std::string& detail, double secondsLeft) {
  static auto last = std::chrono::steady_clock::time_point{};
  const auto now = std::chrono::steady_clock::now();
  if (fraction < 1.0 && now - last < std::chrono::milliseconds(500)) return;
  last = now;
  constexpr int kWidth = 30;
  const int filled = int(std::clamp(fraction, 0.0, 1.0) * kWidth + 0.5);
  std::fprintf(stderr, "\r[%s%s] %s, %.0f s left   ", std::string(size_t(filled), '#').c_str(),
               std::string(size_t(kWidth - filled), ' ').c_str(), detail.c_str(), std::max(0.0, secondsLeft));
}

// The widest 95 % interval of the rows' display errors, half of it, in steps.
double widestHalfInterval(const std::vector<MeasuredRow>& rows, const BenchReference& reference) {
  double widest = 0.0;
  for (const MeasuredRow& r : rows) {
    const ErrorEstimate e = reference.error(r.values).display;
    widest = std::max(widest, 0.5 * (e.rmsHigh() - e.rmsLow()));
  }
  return widest;
}

}  // namespace

ReferenceRun convergeReference(ProgressiveImage& gather, const BenchOptions& options,
                               const std::vector<MeasuredRow>& rows, BenchReference& reference) {
  const auto start = std::chrono::steady_clock::now();
  const int runs = gather.runs();
  const int target = (options.spp + runs - 1) / runs * runs;
  auto runImages = [&] {
    std::vector<LinearImage> images;
    for (int r = 0; r < runs; ++r) images.push_back(gather.runImage(r));
    return images;
  };
  while (gather.samplesPerPixel() < target) {
    gather.addPasses(runs);
    const double elapsed = secondsSince(start);
    const double done = double(gather.samplesPerPixel()) / target;
    showProgress(done, "reference " + std::to_string(gather.samplesPerPixel()) + "/" + std::to_string(target) + " spp",
                 elapsed / done - elapsed);
  }
  reference.setRuns(runImages());
  if (options.precision > 0.0) {
    // The interval narrows as 1/sqrt(spp) or faster, so the passes still needed are about
    // spp ((w / precision)^2 - 1): the time left is estimated from that.
    for (double widest = widestHalfInterval(rows, reference); widest > options.precision;
         widest = widestHalfInterval(rows, reference)) {
      const double elapsed = secondsSince(start);
      if (options.maxSeconds > 0.0 && elapsed >= options.maxSeconds) break;
      if (gather.samplesPerPixel() + runs > kMaxGatherSpp) break;
      const double needed = gather.samplesPerPixel() * (widest * widest / (options.precision * options.precision));
      showProgress(gather.samplesPerPixel() / needed,
                   "reference " + std::to_string(gather.samplesPerPixel()) + " spp, widest half-interval " +
                       std::to_string(widest).substr(0, 5) + " steps (target " +
                       std::to_string(options.precision).substr(0, 5) + ")",
                   elapsed / gather.samplesPerPixel() * (needed - gather.samplesPerPixel()));
      gather.addPasses(runs);
      reference.setRuns(runImages());
    }
  }
  std::fprintf(stderr, "\n");
  return {gather.samplesPerPixel(), secondsSince(start)};
}

}  // namespace radview
