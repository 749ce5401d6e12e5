// libFuzzer target: bytes as another tool's mesh, PLY or OBJ, opened as radview opens them
// (tests/fuzz/fuzz_inputs.h). Seeds: tests/fuzz/CMakeLists.txt.
#include "tests/fuzz/fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  radview::fuzz::importMeshBytes(data, size);
  return 0;
}
