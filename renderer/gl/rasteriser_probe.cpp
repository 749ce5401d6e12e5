#include "gl/rasteriser_probe.h"

#include "core/error.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace radview::gl {

namespace {

constexpr int kSize = 16;  // the probe's viewport, pixels a side

// Window coordinates of the probe triangle's corners, off every 2^-k pixel grid: snapped to
// 1/256 pixel they move by up to 2e-3 pixel, and its barycentric coordinates by about 1e-4.
constexpr std::array<double, 6> kCorners = {2.1234567, 3.0098765, 12.765432, 4.4321234, 6.3579135, 13.975310};

const char* const kVertexSource = R"(#version 450 core
layout(location = 0) in vec2 window;
out vec3 vLambda;
void main() {
  gl_Position = vec4(window / 8.0 - 1.0, 0.0, 1.0);
  vLambda = vec3(gl_VertexID == 0, gl_VertexID == 1, gl_VertexID == 2);
}
)";
const char* const kFragmentSource = R"(#version 450 core
in vec3 vLambda;
layout(location = 0) out vec4 lambda;
void main() { lambda = vec4(vLambda, 1.0); }
)";

GLuint compiled(GLenum stage, const char* source) {
  const GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  return shader;
}

}  // namespace

double rasteriserInterpolationError() {
  // What the probe changes, restored after it.
  GLint drawFramebuffer = 0, readFramebuffer = 0, program = 0, vertexArray = 0, viewport[4] = {};
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer);
  glGetIntegerv(GL_CURRENT_PROGRAM, &program);
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray);
  glGetIntegerv(GL_VIEWPORT, viewport);
  GLint polygonMode[2] = {GL_FILL, GL_FILL}, packBuffer = 0;
  glGetIntegerv(GL_POLYGON_MODE, polygonMode);
  glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &packBuffer);
  GLboolean colourMask[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
  glGetBooleani_v(GL_COLOR_WRITEMASK, 0, colourMask);
  const GLenum packParameters[] = {GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS, GL_PACK_ALIGNMENT};
  std::vector<GLint> packed;
  for (GLenum p : packParameters) {
    GLint value = 0;
    glGetIntegerv(p, &value);
    packed.push_back(value);
    glPixelStorei(p, p == GL_PACK_ALIGNMENT ? 4 : 0);
  }
  const GLenum capabilities[] = {GL_DEPTH_TEST,   GL_BLEND,        GL_CULL_FACE,         GL_SCISSOR_TEST,
                                 GL_STENCIL_TEST, GL_RASTERIZER_DISCARD, GL_CLIP_DISTANCE0, GL_SAMPLE_COVERAGE,
                                 GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_MASK};
  std::vector<GLboolean> enabled;
  for (GLenum c : capabilities) {
    enabled.push_back(glIsEnabled(c));
    glDisable(c);
  }
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  const GLuint vertex = compiled(GL_VERTEX_SHADER, kVertexSource);
  const GLuint fragment = compiled(GL_FRAGMENT_SHADER, kFragmentSource);
  const GLuint probe = glCreateProgram();
  glAttachShader(probe, vertex);
  glAttachShader(probe, fragment);
  glLinkProgram(probe);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint linked = GL_FALSE;
  glGetProgramiv(probe, GL_LINK_STATUS, &linked);

  GLuint texture = 0, framebuffer = 0, buffer = 0, array = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  glTextureStorage2D(texture, 1, GL_RGBA32F, kSize, kSize);
  glCreateFramebuffers(1, &framebuffer);
  glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, texture, 0);
  const std::array<float, 6> corners = {float(kCorners[0]), float(kCorners[1]), float(kCorners[2]),
                                        float(kCorners[3]), float(kCorners[4]), float(kCorners[5])};
  glCreateBuffers(1, &buffer);
  glNamedBufferData(buffer, sizeof corners, corners.data(), GL_STATIC_DRAW);
  glCreateVertexArrays(1, &array);
  glVertexArrayVertexBuffer(array, 0, buffer, 0, 2 * sizeof(float));
  glEnableVertexArrayAttrib(array, 0);
  glVertexArrayAttribFormat(array, 0, 2, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(array, 0, 0);

  std::vector<float> pixels(size_t(4) * kSize * kSize, 0.0f);
  const bool ready = linked && glCheckNamedFramebufferStatus(framebuffer, GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  if (ready) {
    const float clear[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, clear);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, kSize, kSize);
    glUseProgram(GLuint(probe));
    glBindVertexArray(array);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)), pixels.data());
  }

  glDeleteVertexArrays(1, &array);
  glDeleteBuffers(1, &buffer);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteTextures(1, &texture);
  glDeleteProgram(probe);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawFramebuffer));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readFramebuffer));
  glUseProgram(GLuint(program));
  glBindVertexArray(GLuint(vertexArray));
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  for (size_t i = 0; i < enabled.size(); ++i)
    if (enabled[i]) glEnable(capabilities[i]);
  glPolygonMode(GL_FRONT_AND_BACK, GLenum(polygonMode[0]));
  glBindBuffer(GL_PIXEL_PACK_BUFFER, GLuint(packBuffer));
  glColorMaski(0, colourMask[0], colourMask[1], colourMask[2], colourMask[3]);
  for (size_t i = 0; i < packed.size(); ++i) glPixelStorei(packParameters[i], packed[i]);
  if (!ready) return NAN;

  // The pixel centres' own barycentric coordinates (window space is affine here: w = 1).
  const double ax = kCorners[0], ay = kCorners[1], bx = kCorners[2], by = kCorners[3], cx = kCorners[4],
               cy = kCorners[5];
  const double area = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
  double largest = 0.0;
  size_t covered = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const float* p = &pixels[(size_t(y) * kSize + x) * 4];
      if (p[3] == 0.0f) continue;
      ++covered;
      const double px = x + 0.5, py = y + 0.5;
      const double l0 = ((bx - px) * (cy - py) - (cx - px) * (by - py)) / area;
      const double l1 = ((cx - px) * (ay - py) - (ax - px) * (cy - py)) / area;
      const double exact[3] = {l0, l1, 1.0 - l0 - l1};
      for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(double(p[c]) - exact[c]));
    }
  return covered > 0 ? largest : NAN;
}

bool pixelCentreCorrection() {
  static const bool correct = [] {
    if (const char* choice = std::getenv("RADVIEW_PIXEL_CENTRE")) {
      const std::string value = choice;
      if (value == "on") return true;
      if (value == "off") return false;
      throw Error("RADVIEW_PIXEL_CENTRE='" + value + "': expected 'on' or 'off'");
    }
    // A probe that could not run decides for the correction: exact on any rasteriser.
    const double error = rasteriserInterpolationError();
    return !(error <= kSnappedInterpolationError);
  }();
  return correct;
}

}  // namespace radview::gl
