#include "gl/buffer_storage.h"

#include "core/error.h"

#include <sys/mman.h>

#include <cstring>
#include <string>

namespace radview::gl {

namespace {

constexpr size_t kPage = 4096;
// A software rasteriser reads a buffer in blocks that may run up to 48 bytes past its end
// (Mesa's llvmpipe allocates its own buffers that much larger): whole pages, and one cache
// line to spare.
constexpr size_t kSlack = 64;

std::string megabytes(size_t bytes) { return std::to_string((bytes + (1 << 20) - 1) >> 20) + " MB"; }

bool holds(GLuint buffer, size_t bytes) {
  GLint64 size = 0;
  glGetNamedBufferParameteri64v(buffer, GL_BUFFER_SIZE, &size);
  return size == GLint64(bytes);
}

}  // namespace

BufferStorage::BufferStorage(bool pinnedWhereOffered)
    : pinned_(pinnedWhereOffered && epoxy_has_gl_extension("GL_AMD_pinned_memory")) {}

BufferStorage::~BufferStorage() {
  if (held_.empty() && reserved_.empty()) return;
  glFinish();
  for (auto* blocks : {&held_, &reserved_})
    for (auto& [buffer, block] : *blocks)
      if (block.mapped) munmap(block.memory, block.mapped);
}

void BufferStorage::release(Block& block) {
  if (!block.mapped) return;
  glFinish();  // draws already issued may still read it
  munmap(block.memory, block.mapped);
  block = {};
}

std::byte* BufferStorage::reserve(GLuint buffer, size_t bytes) {
  if (auto old = reserved_.find(buffer); old != reserved_.end()) {
    if (old->second.mapped) munmap(old->second.memory, old->second.mapped);
    else if (old->second.memory) glUnmapNamedBuffer(buffer);
    reserved_.erase(old);
  }
  Block block{nullptr, bytes, 0};
  if (pinned_ && bytes > 0) {
    block.mapped = (bytes + kSlack + kPage - 1) / kPage * kPage;
    void* memory = mmap(nullptr, block.mapped, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (memory == MAP_FAILED) throw Error("cannot allocate " + megabytes(bytes) + " for a GL buffer");
    madvise(memory, block.mapped, MADV_HUGEPAGE);  // advice only: failure is harmless
    block.memory = static_cast<std::byte*>(memory);
  } else {
    if (auto held = held_.find(buffer); held != held_.end()) {
      glNamedBufferData(buffer, 0, nullptr, GL_STATIC_DRAW);
      release(held->second);
      held_.erase(held);
    }
    glNamedBufferData(buffer, GLsizeiptr(bytes), nullptr, GL_STATIC_DRAW);
    if (bytes > 0) {
      block.memory = static_cast<std::byte*>(
          glMapNamedBufferRange(buffer, 0, GLsizeiptr(bytes), GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT));
      if (!block.memory) throw Error("the GL could not map " + megabytes(bytes) + " for a buffer");
    }
  }
  reserved_[buffer] = block;
  return block.memory;
}

void BufferStorage::commit(GLuint buffer) {
  auto found = reserved_.find(buffer);
  if (found == reserved_.end()) return;
  Block block = found->second;
  reserved_.erase(found);
  if (!block.mapped) {
    // Unmapping fails only where the GL lost the memory meanwhile (on a display mode change).
    if (block.memory && !glUnmapNamedBuffer(buffer))
      throw Error("the GL lost " + megabytes(block.bytes) + " of a buffer while it was written");
    return;
  }
  // The buffer is emptied first, so that its size tells whether the GL took the memory: a
  // driver may offer the extension and still refuse some memory (GL_INVALID_OPERATION, AMD_
  // pinned_memory), and a refused buffer keeps its old storage.
  glNamedBufferData(buffer, 0, nullptr, GL_STATIC_DRAW);
  glBindBuffer(GL_EXTERNAL_VIRTUAL_MEMORY_BUFFER_AMD, buffer);
  glBufferData(GL_EXTERNAL_VIRTUAL_MEMORY_BUFFER_AMD, GLsizeiptr(block.bytes), block.memory, GL_STATIC_DRAW);
  glBindBuffer(GL_EXTERNAL_VIRTUAL_MEMORY_BUFFER_AMD, 0);
  if (auto held = held_.find(buffer); held != held_.end()) {
    release(held->second);
    held_.erase(held);
  }
  if (holds(buffer, block.bytes)) {
    held_[buffer] = block;
    return;
  }
  // Refused: the GL copies it into storage of its own instead.
  while (glGetError() != GL_NO_ERROR) {
  }
  glNamedBufferData(buffer, GLsizeiptr(block.bytes), block.memory, GL_STATIC_DRAW);
  munmap(block.memory, block.mapped);
  if (!holds(buffer, block.bytes)) {
    while (glGetError() != GL_NO_ERROR) {
    }
    throw Error("the GL took neither " + megabytes(block.bytes) + " of this process's memory as a buffer nor a copy");
  }
}

void BufferStorage::upload(GLuint buffer, const void* data, size_t bytes) {
  std::byte* memory = reserve(buffer, bytes);
  if (bytes > 0) std::memcpy(memory, data, bytes);
  commit(buffer);
}

void BufferStorage::clear(GLuint buffer) {
  reserve(buffer, 0);  // no memory of this process's: the previous storage goes
  commit(buffer);
}

}  // namespace radview::gl
