// Large blocks on transparent huge pages. Opening a mesh of 10^5-10^6 elements touches
// hundreds of megabytes of new memory. On 4 KiB pages each page is a fault, and on a virtual
// machine a fault can cost microseconds, a large share of `radview render`'s time at 10^5-10^6
// elements (tests/bench/README.md). Where the kernel backs memory with
// huge pages only when asked (transparent_hugepage=madvise, the usual setting), blocks of
// 4 MiB and more ask, through the one allocation function every C++ container uses. Smaller
// blocks, and what C libraries allocate, are as before.
//
// Not linked into the sanitizer build (app/CMakeLists.txt): AddressSanitizer checks that what
// operator new returns is freed by its own operator delete, not by free().

#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <new>

namespace {

constexpr std::size_t kHugePageAdviceFrom = std::size_t(4) << 20;

}  // namespace

// operator new[] and the nothrow forms call this one (libstdc++); operator delete frees with
// free(), which glibc's malloc blocks need.
void* operator new(std::size_t size) {
  void* p = std::malloc(size == 0 ? 1 : size);
  if (!p) throw std::bad_alloc();
  if (size >= kHugePageAdviceFrom) {
    // From a mapping of its own or the top of glibc's heap: the advice covers the block's pages.
    constexpr std::uintptr_t kPage = 4096;
    const std::uintptr_t begin = std::uintptr_t(p) & ~(kPage - 1);
    const std::uintptr_t end = (std::uintptr_t(p) + size + kPage - 1) & ~(kPage - 1);
    madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // advice only: failure is harmless
  }
  return p;
}
