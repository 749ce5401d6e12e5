#pragma once
// Storage for the GL buffers a mesh fills, written once by the CPU: 10^8 bytes and more at 10^6
// elements. Where the GL takes this process's own memory as a buffer's storage
// (GL_AMD_pinned_memory, which Mesa's llvmpipe offers), the storage is allocated here, on huge
// pages (app/huge_pages.cpp says why), written in place and handed over as it is. llvmpipe's
// own buffers are zero-filled on 4 KiB pages before they are written: at 4.6e5 elements that
// cost Clough-Tocher's set-up about half a second, a tenth of `radview render`. Elsewhere the
// GL's own storage is mapped and written.
#include <epoxy/gl.h>

#include <cstddef>
#include <map>

namespace radview::gl {

class BufferStorage {
 public:
  // pinnedWhereOffered = false maps the GL's own storage everywhere (the tests run both).
  explicit BufferStorage(bool pinnedWhereOffered = true);
  ~BufferStorage();  // waits for the GL to finish with the memory it holds here, then frees it
  BufferStorage(const BufferStorage&) = delete;
  BufferStorage& operator=(const BufferStorage&) = delete;

  bool pinned() const { return pinned_; }  // whether buffers get this process's memory
  // Gives `buffer` `bytes` of new storage and returns where to write them, until
  // commit(buffer). Throws Error if the GL cannot give them.
  std::byte* reserve(GLuint buffer, size_t bytes);
  // Makes what was written since reserve(buffer) the buffer's contents, and frees its previous
  // storage; where the GL refuses this process's memory, it gets a copy. Throws Error if the GL
  // lost the mapped storage meanwhile, or takes neither the memory nor a copy.
  void commit(GLuint buffer);
  // reserve, copy, commit.
  void upload(GLuint buffer, const void* data, size_t bytes);
  void clear(GLuint buffer);  // empties the buffer and frees its storage

 private:
  struct Block {
    std::byte* memory = nullptr;  // this process's, or the GL's, mapped
    size_t bytes = 0;             // what was reserved
    size_t mapped = 0;            // this process's memory: whole pages
  };
  void release(Block& block);  // frees this process's memory, once the GL is done with it
  bool pinned_ = false;
  std::map<GLuint, Block> held_;      // this process's memory that buffers use
  std::map<GLuint, Block> reserved_;  // written, until committed
};

}  // namespace radview::gl
