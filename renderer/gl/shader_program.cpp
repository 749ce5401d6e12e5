#include "gl/shader_program.h"

#include "core/error.h"
#include "core/strings.h"
#include "gl/embedded_shaders.h"
#include "gl/rasteriser_probe.h"

#include <glm/gtc/type_ptr.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace radview::gl {

namespace {

// The shader file `name` as read: its text, and the path to name in messages.
struct ShaderFile {
  std::string path;
  std::string text;
};

ShaderFile readRaw(const std::string& name) {
  if (const char* dir = std::getenv("RADVIEW_SHADER_DIR")) {
    const std::string path = std::string(dir) + "/" + name;
    std::ifstream in(path);
    if (!in) throw Error(path, "shader file not found (RADVIEW_SHADER_DIR is set)");
    std::stringstream ss;
    ss << in.rdbuf();
    return {path, ss.str()};
  }
  const auto& table = embeddedShaders();
  auto it = table.find(name);
  if (it == table.end()) throw Error("shaders/" + name, "no such shader embedded in this build");
  return {"shaders/" + name, it->second};
}

GLenum stageOf(const std::string& file) {
  const std::string ext = file.substr(file.find_last_of('.') + 1);
  if (ext == "vert") return GL_VERTEX_SHADER;
  if (ext == "tesc") return GL_TESS_CONTROL_SHADER;
  if (ext == "tese") return GL_TESS_EVALUATION_SHADER;
  if (ext == "geom") return GL_GEOMETRY_SHADER;
  if (ext == "frag") return GL_FRAGMENT_SHADER;
  throw Error("shaders/" + file, "unknown shader stage extension");
}

// The stage's source with its includes expanded and `defines` after the #version line.
std::string preprocess(const std::string& text, const std::vector<std::string>& defines) {
  std::istringstream in(text);
  std::ostringstream out;
  const std::string directive = "#include \"";
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("#version", 0) == 0) {
      out << line << '\n';
      for (const std::string& define : defines) out << "#define " << define << '\n';
    } else if (line.rfind(directive, 0) == 0) {
      const std::string included = line.substr(directive.size(), line.find('"', directive.size()) - directive.size());
      // Whether this OpenGL needs it, known only from a probe of it (gl/rasteriser_probe.h).
      if (included == "lib/pixel_centre.glsl")
        out << "#define PIXEL_CENTRE_CORRECTION " << (pixelCentreCorrection() ? 1 : 0) << '\n';
      out << readRaw(included).text << '\n';
    } else {
      out << line << '\n';
    }
  }
  return out.str();
}

// The driver's log for a shader or program, on one line.
template <typename GetLog>
std::string log(GLuint object, GetLog getLog) {
  char text[4096] = {};
  getLog(object, sizeof text, nullptr, text);
  return oneLine(text);
}

}  // namespace

ShaderProgram::ShaderProgram(const std::vector<std::string>& stageFiles, const std::vector<std::string>& defines) {
  // Every source is read and every stage known before a GL object exists, so a missing file
  // leaks nothing.
  struct Stage {
    GLenum type;
    std::string path, source;
  };
  std::vector<Stage> stages;
  for (const std::string& file : stageFiles) {
    const ShaderFile raw = readRaw(file);
    stages.push_back({stageOf(file), raw.path, preprocess(raw.text, defines)});
  }
  std::vector<GLuint> shaders;
  auto releaseShaders = [&] {
    for (GLuint s : shaders) glDeleteShader(s);
  };
  for (const Stage& stage : stages) {
    const GLuint shader = glCreateShader(stage.type);
    shaders.push_back(shader);
    const char* text = stage.source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      const std::string why = log(shader, glGetShaderInfoLog);
      releaseShaders();
      throw Error(stage.path, "does not compile: " + why);
    }
  }
  program_ = glCreateProgram();
  for (GLuint s : shaders) glAttachShader(program_, s);
  glLinkProgram(program_);
  releaseShaders();
  GLint ok = GL_FALSE;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string why = log(program_, glGetProgramInfoLog);
    glDeleteProgram(program_);
    throw Error(stages.front().path, "program does not link: " + why);
  }
}

ShaderProgram::~ShaderProgram() { glDeleteProgram(program_); }

void ShaderProgram::set(const char* name, int value) const { glProgramUniform1i(program_, location(name), value); }
void ShaderProgram::set(const char* name, float value) const { glProgramUniform1f(program_, location(name), value); }
void ShaderProgram::set(const char* name, const glm::vec2& v) const {
  glProgramUniform2fv(program_, location(name), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const char* name, const glm::vec3& v) const {
  glProgramUniform3fv(program_, location(name), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const char* name, const glm::vec4& v) const {
  glProgramUniform4fv(program_, location(name), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const char* name, const glm::mat4& m) const {
  glProgramUniformMatrix4fv(program_, location(name), 1, GL_FALSE, glm::value_ptr(m));
}

void ShaderProgram::setViewportSize() const {
  GLint viewport[4] = {};
  glGetIntegerv(GL_VIEWPORT, viewport);
  set("viewportSize", glm::vec2(viewport[2], viewport[3]));
}

}  // namespace radview::gl
