#include "gl/frame_timing.h"

#include "bench/image_error.h"

#include <epoxy/gl.h>

#include <chrono>

namespace radview::gl {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

FrameTime timeFrame(MeshRenderer& renderer, const Camera& camera, const RenderSettings& settings, int width,
                    int height) {
  const auto start = Clock::now();
  renderer.render(camera, settings, width, height);
  glFinish();
  return {renderer.lastFrameGpuMs(), millisecondsSince(start)};
}

double FrameTimes::medianGpuMs() const {
  std::vector<double> ms;
  for (const FrameTime& frame : frames) ms.push_back(frame.gpuMs);
  return median(ms);
}

double FrameTimes::medianWallMs() const {
  std::vector<double> ms;
  for (const FrameTime& frame : frames) ms.push_back(frame.wallMs);
  return median(ms);
}

FrameTimes timeFrames(MeshRenderer& renderer, const Camera& camera, const RenderSettings& settings, int width,
                      int height, int frames, double seconds) {
  for (int k = 0; k < 2; ++k) timeFrame(renderer, camera, settings, width, height);
  FrameTimes times;
  const auto start = Clock::now();
  for (int k = 0; k < frames; ++k) {
    times.frames.push_back(timeFrame(renderer, camera, settings, width, height));
    if (seconds > 0.0 && times.frames.size() >= 3 && millisecondsSince(start) >= 1e3 * seconds) break;
  }
  return times;
}

}  // namespace radview::gl
