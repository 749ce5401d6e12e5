#include "gather/background_gather.h"

#include "gather/path_tracer.h"
#include "trace/visible_elements.h"

#include <algorithm>
#include <chrono>

#include <sys/resource.h>

namespace radview {

namespace {

using Clock = std::chrono::steady_clock;
constexpr int kPreviewDivisor = 4;  // the preview's pixels are 4x4 of the window's
constexpr int kPreviewSpp = 4;      // a quarter of one full-resolution pass in all

std::unique_ptr<ProgressiveImage> estimate(const RadiosityMesh& mesh, const GatherSettings& settings,
                                           const std::optional<Scene>& pathTraced) {
  if (!pathTraced) return std::make_unique<FinalGather>(mesh, settings);
  PathTraceSettings traced;
  traced.seed = settings.seed;
  traced.width = settings.width;
  traced.height = settings.height;
  traced.camera = settings.camera;
  return std::make_unique<PathTracer>(pathTraced->polygons.empty() ? elementScene(mesh) : *pathTraced, traced);
}

}  // namespace

BackgroundGather::~BackgroundGather() {
  cancel();
  join();
}

void BackgroundGather::join() {
  if (worker_.joinable()) worker_.join();
}

void BackgroundGather::start(const RadiosityMesh& mesh, const GatherSettings& settings, const Scene* pathTraced) {
  cancel();
  join();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    latest_.reset();
    progress_ = GatherProgress{};
    progress_.preview = true;
    workerDone_ = false;
  }
  cancelled_ = false;
  settings_ = settings;
  pathTrace_ = pathTraced != nullptr;
  worker_ = std::thread(&BackgroundGather::run, this, mesh, settings,
                        pathTraced ? std::optional<Scene>(*pathTraced) : std::nullopt);
}

void BackgroundGather::cancel() {
  cancelled_ = true;
  settings_.reset();
  std::lock_guard<std::mutex> lock(mutex_);
  latest_.reset();
  progress_ = GatherProgress{};
  changed_.notify_all();
}

void BackgroundGather::setTarget(int targetSpp, bool paused) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (targetSpp == targetSpp_ && paused == paused_) return;
  targetSpp_ = targetSpp;
  paused_ = paused;
  changed_.notify_all();
}

void BackgroundGather::waitForTarget() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] {
    return workerDone_ || cancelled_ || paused_ || (!progress_.preview && progress_.spp >= targetSpp_);
  });
}

std::optional<LinearImage> BackgroundGather::takeImage() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::optional<LinearImage> out = std::move(latest_);
  latest_.reset();
  return out;
}

GatherProgress BackgroundGather::progress() const {
  std::lock_guard<std::mutex> lock(mutex_);
  GatherProgress p = progress_;
  p.reachedTarget = !p.preview && p.spp >= targetSpp_;
  return p;
}

bool BackgroundGather::waitForWork(int spp) {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return cancelled_ || (!paused_ && spp < targetSpp_); });
  return !cancelled_;
}

void BackgroundGather::run(RadiosityMesh mesh, GatherSettings settings, std::optional<Scene> pathTraced) {
  // Below the frame loop's priority, it and the pass threads it starts (Linux's nice value is
  // per thread and inherited): the gather takes every core, and the window must still draw.
  setpriority(PRIO_PROCESS, 0, 10);
  GatherProgress progress;
  auto since = Clock::now();
  // Adds the time since the last call (or since the end of a wait) to the seconds shown.
  auto clock = [&] {
    const auto now = Clock::now();
    progress.seconds += std::chrono::duration<double>(now - since).count();
    since = now;
  };
  // Publishes the mean under the lock, unless the gather was cancelled meanwhile: the frame
  // loop only ever waits for a move of the image, never for a pass.
  auto publish = [&](LinearImage image) {
    clock();
    std::lock_guard<std::mutex> lock(mutex_);
    if (cancelled_) return;
    latest_ = std::move(image);
    progress_ = progress;
    changed_.notify_all();
  };
  auto waitFor = [&](int spp) {
    clock();
    const bool wanted = waitForWork(spp);
    since = Clock::now();
    return wanted;
  };
  try {
    uint64_t previewRays = 0;
    {
      GatherSettings small = settings;
      small.width = std::max(1, settings.width / kPreviewDivisor);
      small.height = std::max(1, settings.height / kPreviewDivisor);
      const std::unique_ptr<ProgressiveImage> preview = estimate(mesh, small, pathTraced);
      progress.preview = true;
      while (preview->samplesPerPixel() < kPreviewSpp && waitFor(0) && preview->addPasses(1, &cancelled_) == 1) {
        progress.rays = previewRays = preview->raysCast();
        publish(preview->image());
      }
    }
    if (!cancelled_) {
      const std::unique_ptr<ProgressiveImage> gather = estimate(mesh, settings, pathTraced);
      while (waitFor(gather->samplesPerPixel()) && gather->addPasses(1, &cancelled_) == 1) {
        progress.preview = false;
        progress.spp = gather->samplesPerPixel();
        progress.rays = previewRays + gather->raysCast();
        publish(gather->image());
      }
    }
  } catch (const std::exception& e) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!cancelled_)
      progress_.error = std::string(pathTraced ? "path tracer" : "final gather") + " failed: " + e.what();
  }
  std::lock_guard<std::mutex> lock(mutex_);
  workerDone_ = true;
  changed_.notify_all();
}

}  // namespace radview
