#include "gl/gpu_timer.h"

#include "core/error.h"

namespace radview::gl {

GpuTimer::GpuTimer() {
  for (GlObject& query : queries_) query = GlObject(GlKind::TimerQuery);
}

void GpuTimer::begin() {
  const GLuint query = queries_[frame_ % 2];
  if (frame_ >= 2) {
    GLint ready = 0;
    glGetQueryObjectiv(query, GL_QUERY_RESULT_AVAILABLE, &ready);
    if (ready) {
      GLuint64 ns = 0;
      glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);
      recentMs_ = double(ns) * 1e-6;
    }
  }
  glBeginQuery(GL_TIME_ELAPSED, query);
}

void GpuTimer::end() {
  glEndQuery(GL_TIME_ELAPSED);
  ++frame_;
}

double GpuTimer::lastMs() const {
  if (frame_ == 0) throw Error("the GPU frame time was asked for before any frame was rendered");
  GLuint64 ns = 0;
  glGetQueryObjectui64v(queries_[(frame_ - 1) % 2], GL_QUERY_RESULT, &ns);
  return double(ns) * 1e-6;
}

}  // namespace radview::gl
