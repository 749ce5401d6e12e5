#pragma once
// The C1 interpolants exactly per pixel, deferred (a visibility buffer): one raster pass of the
// element triangles, as cheap as Gouraud's, writes which triangle each pixel sees and the
// barycentric coordinates of its surface point (with depth); one full-screen pass then
// evaluates the Bezier piece holding that point from control values uploaded once per mesh
// (gl/patch_nets.h). Each visible pixel is evaluated once, whatever the depth complexity, and
// the GPU holds 36 bytes of corners and 144 of control values per triangle, where drawing
// every piece as its own triangle with its net on each vertex took 1,440 (Clough-Tocher) and
// 2,880 (Powell-Sabin) (C&W §9.2.2).
#include "gl/buffer_storage.h"
#include "gl/patch_nets.h"
#include "gl/shader_program.h"

#include <epoxy/gl.h>

#include <functional>
#include <string>

namespace radview::gl {

class DeferredPass {
 public:
  DeferredPass();
  ~DeferredPass();
  DeferredPass(const DeferredPass&) = delete;
  DeferredPass& operator=(const DeferredPass&) = delete;

  // fill(corners, nets) writes every triangle: 3 corners and kNetVec4s vec4 each (gl/patch_nets.h).
  using NetFill = std::function<void(glm::vec3* corners, glm::vec4* nets)>;
  // Allocates room for `triangles` triangles of pieces of `degree`, then has `fill` write them
  // all, once, straight into the GL's buffers (gl/buffer_storage.h): the CPU holds no copy of
  // its own.
  // Throws Error for more than this OpenGL's buffer textures hold, or than a float counts
  // exactly (2^24 - 1, the visibility pass's triangle numbers).
  void upload(size_t triangles, int degree, const NetFill& fill);
  void clear();  // frees the GPU's copy
  size_t triangles() const { return triangles_; }
  // Linear radiosity into `target` (a framebuffer whose colour is an RGBA32F texture, cleared to
  // 0, with depth, depth testing set up by the caller, who also restores it), leaving the
  // surfaces' depth behind. Deferred: the visibility raster writes into that colour texture
  // what each pixel sees, (triangle + 1, lambda), 0 for the background; the evaluation then
  // reads each pixel's own texel and overwrites it, so that no visibility buffer is needed
  // beside it. Or in one pass while the draw has fewer vertices than the viewport has pixels,
  // which reads less (tests/bench/README.md): each Clough-Tocher vertex reads its own corner's
  // values as vertex attributes, each C1 quadratic vertex its triangle's as texels.
  void draw(const glm::mat4& clipFromWorld, GLuint target);
  // The surfaces' depth alone, into the bound framebuffer (the visibility raster, its colour
  // writes masked by the caller): what overlays are depth-tested against.
  void drawDepth(const glm::mat4& clipFromWorld);

 private:
  void drawDeferred(const glm::mat4& clipFromWorld, GLuint target);
  BufferStorage storage_;  // freed after ~DeferredPass deletes the buffers that use it
  void drawForward(const glm::mat4& clipFromWorld, GLuint target);
  ShaderProgram visibility_{{"visibility.vert", "visibility.frag"}};
  // One evaluation program per degree, quadratic [0] and cubic [1], and so the one-pass ones.
  static ShaderProgram program(const char* vertex, const char* fragment, int degree) {
    return ShaderProgram({vertex, fragment},
                         {"DEGREE " + std::to_string(degree), "NET_VEC4S " + std::to_string(kNetVec4s)});
  }
  ShaderProgram resolve_[2] = {program("fullscreen.vert", "deferred_resolve.frag", 2),
                               program("fullscreen.vert", "deferred_resolve.frag", 3)};
  ShaderProgram forward_[2] = {program("c1_forward.vert", "c1_forward.frag", 2),
                               program("c1_forward.vert", "c1_forward.frag", 3)};
  // Triangle numbers travel as floats, exact below 2^24.
  static constexpr size_t kMaxTriangles = size_t(1) << 24;
  GLuint vao_ = 0, oneCornerVao_[2] = {}, corners_ = 0, nets_ = 0, netsTexture_ = 0,
         emptyVao_ = 0;  // nets_ read as a buffer texture
  size_t triangles_ = 0;
  int degree_ = 3;
};

}  // namespace radview::gl
