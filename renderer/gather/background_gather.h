#pragma once
// The final gather (C&W §9.3.1, eq. 9.9; final_gather.h) or the path tracer (path_tracer.h)
// run beside a frame loop, as BackgroundSolve (solve/background_solve.h) runs the solve: a
// worker thread adds passes of one sample per pixel and publishes the mean after each, so a
// window shows it converging, until it has the samples per pixel asked for (it then waits,
// keeping its mean, in case more are asked for).
//
// Each gather first makes a preview at a quarter of the resolution (1/16 of the rays), so that
// a picture appears long before a full-resolution pass is done.
#include "gather/final_gather.h"
#include "gather/progressive_image.h"
#include "mesh/radiosity_mesh.h"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace radview {

// What the panel shows of a gather.
struct GatherProgress {
  bool preview = false;        // the quarter-resolution preview is what is published so far
  int spp = 0;                 // samples per pixel of the full-resolution mean (0 during the preview)
  double seconds = 0.0;        // spent gathering, previews and set-up included, waiting not
  uint64_t rays = 0;           // cast, previews included
  bool reachedTarget = false;  // it has the samples asked for and waits
  std::string error;           // why it stopped, if it failed
};

class BackgroundGather {
 public:
  BackgroundGather() = default;
  ~BackgroundGather();  // cancels and waits for the worker
  BackgroundGather(const BackgroundGather&) = delete;
  BackgroundGather& operator=(const BackgroundGather&) = delete;

  // Starts gathering a copy of `mesh`, or with `pathTraced` path tracing (which takes only the
  // settings' size, camera and seed) a copy of its polygons, or of the mesh's elements where it
  // has none; after cancelling the gather under way and waiting for its worker to leave (within
  // one row of a pass, or a gather's set-up).
  void start(const RadiosityMesh& mesh, const GatherSettings& settings, const Scene* pathTraced = nullptr);
  // Stops the gather at once, without waiting for its worker: nothing more of it is published
  // and nothing already published is handed out.
  void cancel();
  // The settings of the gather started last and not cancelled since; nothing if none.
  const std::optional<GatherSettings>& settings() const { return settings_; }
  bool pathTracing() const { return pathTrace_; }

  // Adds passes until the full-resolution mean has `targetSpp` samples per pixel, while not paused.
  void setTarget(int targetSpp, bool paused);
  // Blocks until the gather has reached its target, failed, been cancelled or paused: the last frame of
  // `--frames N` waits here so that its screenshot shows a known number of samples.
  void waitForTarget();

  // The latest published mean (row 0 the top, alpha coverage), once per publication.
  std::optional<LinearImage> takeImage();
  GatherProgress progress() const;

 private:
  void run(RadiosityMesh mesh, GatherSettings settings, std::optional<Scene> pathTraced);
  // Waits until a pass is wanted (the target is above `spp` and not paused) or the gather is
  // cancelled; false when cancelled.
  bool waitForWork(int spp);
  void join();

  std::thread worker_;
  std::optional<GatherSettings> settings_;
  bool pathTrace_ = false;
  std::atomic<bool> cancelled_{false};
  mutable std::mutex mutex_;         // guards the fields below
  std::condition_variable changed_;  // the target, pause, cancellation or progress changed
  int targetSpp_ = 1;
  bool paused_ = false;
  bool workerDone_ = true;
  std::optional<LinearImage> latest_;
  GatherProgress progress_;
};

}  // namespace radview
