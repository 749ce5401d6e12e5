#pragma once
// OpenGL objects owned as C++ resources: a GlObject creates its object (DSA, OpenGL 4.5) and
// deletes it when it goes; it moves but does not copy, and converts to its GLuint name for GL
// calls. Needs a current context for its whole life.
#include <epoxy/gl.h>

#include <utility>

namespace radview::gl {

enum class GlKind { Buffer, VertexArray, Texture2D, TextureBuffer, Framebuffer, TimerQuery };

class GlObject {
 public:
  GlObject() = default;  // no object
  explicit GlObject(GlKind kind);
  ~GlObject() { reset(); }
  GlObject(GlObject&& other) noexcept : kind_(other.kind_), id_(std::exchange(other.id_, 0)) {}
  GlObject& operator=(GlObject&& other) noexcept {
    if (this != &other) {
      reset();
      kind_ = other.kind_;
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;

  // Takes ownership of a name made elsewhere.
  static GlObject adopt(GlKind kind, GLuint id);

  operator GLuint() const { return id_; }  // NOLINT: GL calls take the name
  void reset();                            // deletes the object, if any

 private:
  GlKind kind_ = GlKind::Buffer;
  GLuint id_ = 0;
};

}  // namespace radview::gl
