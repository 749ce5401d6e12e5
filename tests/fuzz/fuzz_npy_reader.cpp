// libFuzzer target: bytes as a .npy array, as `radview sample --points FILE.npy` reads them
// (tests/fuzz/fuzz_inputs.h). Seeds: tests/data/*.npy.
#include "tests/fuzz/fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  radview::fuzz::parseNpyBytes(data, size);
  return 0;
}
