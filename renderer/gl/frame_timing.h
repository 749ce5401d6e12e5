#pragma once
// How long frames of one view take, measured one way for every table that reports it
// (`radview bench`, tests/bench/scale_bench.cpp): the GPU's own time for the frame's passes
// (timer queries) and the wall time to the frame's end (the frame drawn, then glFinish).
#include "core/camera.h"
#include "gl/mesh_renderer.h"

#include <vector>

namespace radview::gl {

struct FrameTime {
  double gpuMs = 0.0;   // MeshRenderer::lastFrameGpuMs
  double wallMs = 0.0;  // from the call to the frame's end
};

// Draws one frame of `settings` at width x height and waits for it to finish.
FrameTime timeFrame(MeshRenderer& renderer, const Camera& camera, const RenderSettings& settings, int width,
                    int height);

struct FrameTimes {
  std::vector<FrameTime> frames;
  double medianGpuMs() const;
  double medianWallMs() const;
};

// Two frames untimed first, which build the method's pieces and warm the caches; then up to
// `frames` timed ones, stopping early once at least three are timed and `seconds` have passed
// (0: never).
FrameTimes timeFrames(MeshRenderer& renderer, const Camera& camera, const RenderSettings& settings, int width,
                      int height, int frames, double seconds);

}  // namespace radview::gl
