#include "gl/gl_object.h"

namespace radview::gl {

GlObject::GlObject(GlKind kind) : kind_(kind) {
  switch (kind) {
    case GlKind::Buffer:
      glCreateBuffers(1, &id_);
      break;
    case GlKind::VertexArray:
      glCreateVertexArrays(1, &id_);
      break;
    case GlKind::Texture2D:
      glCreateTextures(GL_TEXTURE_2D, 1, &id_);
      break;
    case GlKind::TextureBuffer:
      glCreateTextures(GL_TEXTURE_BUFFER, 1, &id_);
      break;
    case GlKind::Framebuffer:
      glCreateFramebuffers(1, &id_);
      break;
    case GlKind::TimerQuery:
      glCreateQueries(GL_TIME_ELAPSED, 1, &id_);
      break;
  }
}

GlObject GlObject::adopt(GlKind kind, GLuint id) {
  GlObject object;
  object.kind_ = kind;
  object.id_ = id;
  return object;
}

void GlObject::reset() {
  if (id_ == 0) return;
  switch (kind_) {
    case GlKind::Buffer:
      glDeleteBuffers(1, &id_);
      break;
    case GlKind::VertexArray:
      glDeleteVertexArrays(1, &id_);
      break;
    case GlKind::Texture2D:
    case GlKind::TextureBuffer:
      glDeleteTextures(1, &id_);
      break;
    case GlKind::Framebuffer:
      glDeleteFramebuffers(1, &id_);
      break;
    case GlKind::TimerQuery:
      glDeleteQueries(1, &id_);
      break;
  }
  id_ = 0;
}

}  // namespace radview::gl
