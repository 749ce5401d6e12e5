#pragma once
// GLSL programs built from the files of shaders/ (embedded at build time; RADVIEW_SHADER_DIR
// points at a shaders/ folder to read them from disk instead while developing). A shader may
// `#include "lib/name.glsl"` after its #version line; a program may define macros for all its
// stages (compile-time choices: llvmpipe pays for both sides of a branch on a uniform).
#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace radview::gl {

class ShaderProgram {
 public:
  // Stage from the file extension (.vert .tesc .tese .geom .frag). Throws Error with the
  // file name and the driver's log if a stage does not compile or the program does not link.
  // `defines` ("NAME VALUE" each) become #define lines after each stage's #version line.
  explicit ShaderProgram(const std::vector<std::string>& stageFiles, const std::vector<std::string>& defines = {});
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void use() const { glUseProgram(program_); }
  void set(const char* name, int value) const;
  void set(const char* name, float value) const;
  void set(const char* name, const glm::vec2& value) const;
  void set(const char* name, const glm::vec3& value) const;
  void set(const char* name, const glm::vec4& value) const;
  void set(const char* name, const glm::mat4& value) const;
  // "viewportSize" from the current viewport (shaders/lib/pixel_centre.glsl).
  void setViewportSize() const;

 private:
  GLint location(const char* name) const { return glGetUniformLocation(program_, name); }
  GLuint program_ = 0;
};

}  // namespace radview::gl
