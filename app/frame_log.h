#pragma once
// The viewer's frame log (--frame-log FILE): a line per frame, flushed as it is written, so
// that a script driving the window (tests/bench/edit_latency.sh) can time an input from the
// moment it sent it to the end of the first frame that shows its effect.
#include "interp/methods.h"

#include <cstdint>
#include <cstdio>
#include <string>

namespace radview {

class FrameLog {
 public:
  // Throws Error naming the file when it cannot be written.
  explicit FrameLog(const std::string& path);
  ~FrameLog();
  FrameLog(const FrameLog&) = delete;
  FrameLog& operator=(const FrameLog&) = delete;

  // A frame that has just been swapped to the screen: `wanted` is the method asked for, `drawn`
  // the one drawn (Gouraud while a C1 method's pieces are set up beside the loop), `meshVersion`
  // the renderer's mesh (one more for every edit, undo, solve step or file opened).
  void record(int frame, double cpuMs, Method wanted, Method drawn, uint64_t meshVersion);

 private:
  std::FILE* file_ = nullptr;
  std::string path_;
};

}  // namespace radview
