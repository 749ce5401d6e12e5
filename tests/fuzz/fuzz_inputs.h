#pragma once
// What each fuzz target does with one input. Shared by the libFuzzer targets (built in the
// sanitizer build with clang, tests/fuzz/CMakeLists.txt) and by the unit test that replays the
// seeds and every saved regression input in every build.
//
// An input may be refused with radview::Error (the expected fate of most mutated files); any
// other exception, a sanitizer report, a crash, a hang or a non-finite value is a bug.
#include "mesh/radiosity_mesh.h"

#include <cstddef>
#include <cstdint>

namespace radview::fuzz {

// Writes the bytes to a file in a private temporary directory (.glb when they start with
// glTF's binary magic, else .gltf) and opens it as the viewer does: loadFile, then for a
// scene a coarse uniform mesh lit by its emitters; then exerciseMesh. Returns false when
// radview refuses the file.
bool openGltfBytes(const uint8_t* data, size_t size);

// Bytes as another tool's mesh: starting with "ply", parsed in memory as PLY (import/ply_file.h)
// and made a mesh (import/ply_mesh.h); otherwise written to a file as .obj and opened through
// Assimp as loadFile does; then exerciseMesh. Returns false when radview refuses the file.
bool importMeshBytes(const uint8_t* data, size_t size);

// Bytes as a .npy array (core/npy_array.h), parsed in memory; a parsed array must hold exactly
// rows x columns numbers. Returns false when radview refuses the bytes.
bool parseNpyBytes(const uint8_t* data, size_t size);

// Decodes a mesh (tests/fuzz/mesh_bytes.h) and, if validateMesh accepts it, exerciseMesh.
// Returns false when the mesh is refused.
bool buildMeshBytes(const uint8_t* data, size_t size);

// Builds everything radview derives from a valid mesh (the mesh builder): topology (shared
// positions, adjacency, T-vertex detection), the display triangles and overlays, the
// T-vertex repair, and every interpolant (gradient estimation, Clough-Tocher and
// Powell-Sabin patches); evaluates each interpolant at every element's corner mean and
// aborts, naming the method and element, if B or its gradient is not finite.
// Throws Error where radview refuses the mesh (a discontinuity edge that is no element edge).
void exerciseMesh(const RadiosityMesh& mesh);

}  // namespace radview::fuzz
