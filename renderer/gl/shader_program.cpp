#include "gl/shader_program.h"

#include "core/error.h"
#include "gl/embedded_shaders.h"

#include <glm/gtc/type_ptr.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace radview::gl {

namespace {

std::string readRaw(const std::string& name) {
  if (const char* dir = std::getenv("RADVIEW_SHADER_DIR")) {
    std::ifstream in(std::string(dir) + "/" + name);
    if (!in) throw Error(std::string(dir) + "/" + name, "shader file not found (RADVIEW_SHADER_DIR is set)");
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
  const auto& table = embeddedShaders();
  auto it = table.find(name);
  if (it == table.end()) throw Error("shaders/" + name, "no such shader embedded in this build");
  return it->second;
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

}  // namespace

std::string shaderSource(const std::string& name) {
  std::istringstream in(readRaw(name));
  std::ostringstream out;
  const std::string directive = "#include \"";
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(directive, 0) == 0) {
      const std::string included = line.substr(directive.size(), line.find('"', directive.size()) - directive.size());
      out << readRaw(included) << '\n';
    } else {
      out << line << '\n';
    }
  }
  return out.str();
}

ShaderProgram::ShaderProgram(const std::vector<std::string>& stageFiles) {
  program_ = glCreateProgram();
  std::vector<GLuint> shaders;
  for (const std::string& file : stageFiles) {
    const std::string source = shaderSource(file);
    const char* text = source.c_str();
    GLuint shader = glCreateShader(stageOf(file));
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      char log[4096] = {};
      glGetShaderInfoLog(shader, sizeof log, nullptr, log);
      glDeleteShader(shader);
      for (GLuint s : shaders) glDeleteShader(s);
      glDeleteProgram(program_);
      throw Error("shaders/" + file, std::string("does not compile: ") + log);
    }
    glAttachShader(program_, shader);
    shaders.push_back(shader);
  }
  glLinkProgram(program_);
  for (GLuint s : shaders) glDeleteShader(s);
  GLint ok = GL_FALSE;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetProgramInfoLog(program_, sizeof log, nullptr, log);
    glDeleteProgram(program_);
    throw Error("shaders/" + stageFiles.front(), std::string("program does not link: ") + log);
  }
}

ShaderProgram::~ShaderProgram() { glDeleteProgram(program_); }

void ShaderProgram::set(const char* name, int value) const { glProgramUniform1i(program_, location(name), value); }
void ShaderProgram::set(const char* name, float value) const { glProgramUniform1f(program_, location(name), value); }
void ShaderProgram::set(const char* name, const glm::vec3& v) const {
  glProgramUniform3fv(program_, location(name), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const char* name, const glm::vec4& v) const {
  glProgramUniform4fv(program_, location(name), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const char* name, const glm::mat4& m) const {
  glProgramUniformMatrix4fv(program_, location(name), 1, GL_FALSE, glm::value_ptr(m));
}

}  // namespace radview::gl
