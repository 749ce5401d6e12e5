// libFuzzer target: bytes as a glTF scene or solution file, opened as radview opens files
// (tests/fuzz/fuzz_inputs.h). Seeds: tests/fuzz/CMakeLists.txt.
#include "tests/fuzz/fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  radview::fuzz::openGltfBytes(data, size);
  return 0;
}
