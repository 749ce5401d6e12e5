#pragma once
// A compact byte encoding of small radiosity meshes, so that a fuzzer's byte mutations become
// structural ones: nodes moved onto each other or onto edges (T-vertices, slivers, zero-area
// elements), polygons of 3 to 6 corners, quadratic elements, discontinuity tags, radiosities
// from 1e-8 to 1e8. Every byte string decodes to some mesh (reads past the end give zeros);
// whether it is a valid one is validateMesh's to say.
//
// Layout, little-endian:
//   u16 node count (at most kMaxFuzzNodes), u16 element count (at most kMaxFuzzElements)
//   per node:    3 x i16 position (units of 1/256), 3 x u16 B mantissa (units of 1/256),
//                u8 decade: B is multiplied by 10^(decade % 17 - 8)
//   per element: u8 shape: 3 + (shape & 3) corners, quadratic if shape & 4;
//                u16 corner node per corner, then (quadratic) u16 mid-edge node per edge,
//                node indices taken modulo the node count
//   u16 discontinuity count (at most kMaxFuzzDiscontinuities),
//   per edge:    u16 a, u16 b (modulo the node count), u8 order: (order % 3) - 1
#include "mesh/radiosity_mesh.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace radview::fuzz {

// Small enough that one input runs in milliseconds, large enough for every bundled solution
// but the Cornell box to be a seed.
constexpr size_t kMaxFuzzNodes = 1024;
constexpr size_t kMaxFuzzElements = 1024;
constexpr size_t kMaxFuzzDiscontinuities = 256;

RadiosityMesh decodeMesh(const uint8_t* data, size_t size);

// The inverse, up to rounding: positions are rescaled to fill the i16 range (the mesh keeps
// its shape, not its size), B to three significant digits. Meshes over the limits above are
// truncated (elements naming dropped nodes then name other nodes).
std::vector<uint8_t> encodeMesh(const RadiosityMesh& mesh);

}  // namespace radview::fuzz
