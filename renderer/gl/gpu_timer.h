#pragma once
// The GPU's own time for a frame's passes, by timer queries (GL_TIME_ELAPSED): two in flight, so
// that the viewer reads a result two frames late without ever stalling, and a benchmark waits
// for the last one.
#include "gl/gl_object.h"

#include <array>

namespace radview::gl {

class GpuTimer {
 public:
  GpuTimer();
  // Around a frame's GL commands. begin() first picks up the result of the frame begun two
  // frames ago, if it is ready.
  void begin();
  void end();
  // The most recent frame whose result was ready at begin(), in ms (0 until one was).
  double recentMs() const { return recentMs_; }
  // The last frame's, in ms, waiting for the GPU to finish it. Throws Error before any frame.
  double lastMs() const;

 private:
  std::array<GlObject, 2> queries_;
  int frame_ = 0;  // frames begun
  double recentMs_ = 0.0;
};

}  // namespace radview::gl
