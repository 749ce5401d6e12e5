#pragma once
// The final gather or the path tracer in the viewer's window: when it restarts, and what the
// window shows of it.
//
// A gather is of one view: it restarts when the camera, the framebuffer size, the mesh (another
// file, a solve's new solution) or its own settings change; exposure is not among them, since
// the renderer tone-maps the gather's linear mean every frame. While the view changes the GL
// method is drawn, and the gather restarts once the view has been still for a moment:
// restarting it every frame of a drag would spend each frame on setting up a gather (its ray
// caster, a million pixels' sums) that is cancelled before its first pass.
#include "gather/background_gather.h"
#include "app/viewer_panel.h"
#include "gl/mesh_renderer.h"

#include <chrono>
#include <cstdint>
#include <optional>

namespace radview {

class ViewerGather {
 public:
  // Once a frame, before the renderer draws: starts, restarts or stops the gather as `controls`
  // and the view ask, hands its latest mean to `renderer` (or takes the mean of an outdated
  // view away), and reports its progress in `controls`. `meshVersion` changes whenever `mesh`
  // does. With `waitForTarget`, it first waits for the gather to reach its target (the last
  // frame of --frames with --spp, so that a screenshot shows a known number of samples).
  // `scene`: the file's polygons, which the path tracer traces in place of the mesh's elements
  // when there are any (a scene's; a solution's are empty).
  void update(GatherControls& controls, const RadiosityMesh& mesh, const Scene& scene, uint64_t meshVersion,
              const Camera& camera,
              int width, int height, gl::MeshRenderer& renderer, bool waitForTarget);

 private:
  using Clock = std::chrono::steady_clock;
  BackgroundGather gather_;
  uint64_t gatheredMesh_ = 0;                 // the mesh version the gather under way is of
  std::optional<GatherSettings> lastWanted_;  // the view asked for in the last frame
  uint64_t lastWantedMesh_ = 0;
  bool lastWantedPathTrace_ = false;
  Clock::time_point changedAt_;  // when what is asked for last changed
};

}  // namespace radview
