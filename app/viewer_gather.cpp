#include "app/viewer_gather.h"

#include "core/error.h"
#include "core/memory_budget.h"

#include <string>

namespace radview {

namespace {

// How long the view must stay unchanged before the gather restarts: a pause in a drag, not
// long enough to notice after a key press or a panel change.
constexpr auto kSettle = std::chrono::milliseconds(150);

}  // namespace

void ViewerGather::update(GatherControls& controls, const RadiosityMesh& mesh, const Scene& scene,
                          uint64_t meshVersion, const Camera& camera, int width, int height, gl::MeshRenderer& renderer, bool waitForTarget) {
  if (!controls.on) {
    if (gather_.settings()) gather_.cancel();
    renderer.clearShownImage();
    lastWanted_.reset();
    controls.progress = GatherProgress{};
    return;
  }
  GatherSettings wanted;
  wanted.interpolant = controls.interpolant;
  wanted.seed = controls.seed;
  wanted.width = width;
  wanted.height = height;
  wanted.camera = camera;
  wanted.emitterSamples = controls.emitterSamples;
  const auto now = Clock::now();
  if (!lastWanted_) {
    changedAt_ = now - kSettle;  // just turned on: start at once
  } else if (*lastWanted_ != wanted || lastWantedMesh_ != meshVersion || lastWantedPathTrace_ != controls.pathTrace) {
    changedAt_ = now;
  }
  lastWanted_ = wanted;
  lastWantedMesh_ = meshVersion;
  lastWantedPathTrace_ = controls.pathTrace;

  const bool current = gather_.settings() && *gather_.settings() == wanted && gatheredMesh_ == meshVersion &&
                       gather_.pathTracing() == controls.pathTrace;
  if (!current) {
    if (gather_.settings()) gather_.cancel();
    renderer.clearShownImage();  // its mean is of another view
    if (now - changedAt_ >= kSettle) {
      // The window may have grown since the start-up check (runViewer): a gather too large for
      // the memory available is turned off and said so, and the GL method drawn instead.
      try {
        checkMemory("window " + std::to_string(width) + "x" + std::to_string(height),
                    controls.pathTrace ? "the path tracer" : "the final gather",
                    uint64_t(width) * uint64_t(height) * kGatherBytesPerPixel);
      } catch (const Error&) {
        controls.on = false;
        throw;
      }
      gather_.start(mesh, wanted, controls.pathTrace ? &scene : nullptr);
      gatheredMesh_ = meshVersion;
    }
  }
  gather_.setTarget(controls.targetSpp, controls.paused);
  if (waitForTarget) gather_.waitForTarget();
  if (std::optional<LinearImage> image = gather_.takeImage()) renderer.setShownImage(*image);
  controls.progress = gather_.progress();
}

}  // namespace radview
