// Buffers written in place (gl/buffer_storage.h): in this process's memory where the GL takes
// it (llvmpipe), in the GL's own mapped storage elsewhere; both ways on every GL here.
#include "gl/buffer_storage.h"
#include "core/error.h"
#include "gl/egl_context.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cstring>
#include <iostream>
#include <numeric>
#include <string>
#include <vector>

namespace radview::gl {
namespace {

std::vector<float> contents(GLuint buffer) {
  GLint64 bytes = 0;
  glGetNamedBufferParameteri64v(buffer, GL_BUFFER_SIZE, &bytes);
  std::vector<float> values(size_t(bytes) / sizeof(float));
  glGetNamedBufferSubData(buffer, 0, GLsizeiptr(values.size() * sizeof(float)), values.data());
  return values;
}

// Sums a buffer texture's texels on the GPU: what a shader reads from the storage.
float sumOnTheGpu(GLuint buffer, int texels) {
  const char* source = R"(#version 450 core
layout(local_size_x = 1) in;
layout(binding = 0) uniform samplerBuffer values;
layout(std430, binding = 0) buffer Sum { float sum; };
uniform int count;
void main() { float s = 0.0; for (int i = 0; i < count; ++i) s += texelFetch(values, i).x; sum = s; }
)";
  const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  const GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  glLinkProgram(program);
  GLuint texture = 0, sum = 0;
  glCreateTextures(GL_TEXTURE_BUFFER, 1, &texture);
  glTextureBuffer(texture, GL_R32F, buffer);
  glCreateBuffers(1, &sum);
  const float zero = 0.0f;
  glNamedBufferData(sum, sizeof zero, &zero, GL_STATIC_READ);
  glUseProgram(program);
  glProgramUniform1i(program, glGetUniformLocation(program, "count"), texels);
  glBindTextureUnit(0, texture);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, sum);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  float result = 0.0f;
  glGetNamedBufferSubData(sum, 0, sizeof result, &result);
  glDeleteBuffers(1, &sum);
  glDeleteTextures(1, &texture);
  glDeleteProgram(program);
  glDeleteShader(shader);
  return result;
}

void writeReplaceAndClear(bool pinnedWhereOffered) {
  BufferStorage storage(pinnedWhereOffered);
  GLuint buffer = 0;
  glCreateBuffers(1, &buffer);

  // Written in place, then read back and by a shader.
  std::vector<float> values(1000);
  std::iota(values.begin(), values.end(), 1.0f);
  std::byte* memory = storage.reserve(buffer, values.size() * sizeof(float));
  ASSERT_NE(memory, nullptr);
  std::memcpy(memory, values.data(), values.size() * sizeof(float));
  storage.commit(buffer);
  EXPECT_EQ(contents(buffer), values);
  EXPECT_FLOAT_EQ(sumOnTheGpu(buffer, 1000), 500500.0f);

  // New storage of another size replaces the old, which a draw has just read.
  const std::vector<float> fewer = {7.0f, 8.0f, 9.0f};
  storage.upload(buffer, fewer.data(), fewer.size() * sizeof(float));
  EXPECT_EQ(contents(buffer), fewer);
  EXPECT_FLOAT_EQ(sumOnTheGpu(buffer, 3), 24.0f);

  storage.clear(buffer);
  EXPECT_TRUE(contents(buffer).empty());
  storage.upload(buffer, nullptr, 0);
  EXPECT_TRUE(contents(buffer).empty());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glDeleteBuffers(1, &buffer);
}

TEST(BufferStorage, WritesReplacesAndClearsInTheProcesssMemoryWhereTheGlTakesIt) {
  EglContext context;
  std::cout << context.description() << ": GL_AMD_pinned_memory "
            << (BufferStorage().pinned() ? "offered" : "not offered") << "\n";
  writeReplaceAndClear(true);
}

TEST(BufferStorage, WritesReplacesAndClearsTheGlsOwnStorage) {
  EglContext context;
  EXPECT_FALSE(BufferStorage(false).pinned());
  writeReplaceAndClear(false);
}

// A buffer whose storage the GL will not replace (immutable) takes neither this process's
// memory nor a copy: a clear error, no GL error left behind, and the buffer as it was.
TEST(BufferStorage, StorageTheGlRefusesIsAnError) {
  EglContext context;
  BufferStorage storage;
  if (!storage.pinned()) GTEST_SKIP() << "GL_AMD_pinned_memory not offered";
  GLuint buffer = 0;
  glCreateBuffers(1, &buffer);
  const std::vector<float> before = {1.0f, 2.0f};
  glNamedBufferStorage(buffer, GLsizeiptr(before.size() * sizeof(float)), before.data(), 0);
  const std::vector<float> values(100, 3.0f);
  try {
    storage.upload(buffer, values.data(), values.size() * sizeof(float));
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("took neither"), std::string::npos) << e.what();
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(contents(buffer), before);
  glDeleteBuffers(1, &buffer);
}

}  // namespace
}  // namespace radview::gl
