// libFuzzer target: bytes as a small radiosity mesh (tests/fuzz/mesh_bytes.h) run through the
// mesh builder: topology, T-vertices, gradients, C1 patches, every interpolant.
#include "tests/fuzz/fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  radview::fuzz::buildMeshBytes(data, size);
  return 0;
}
