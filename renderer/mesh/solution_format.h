#pragma once
// What radview's solution writer and reader agree on beyond the public interface
// (mesh/solution_file.h): the format's version, the bufferView targets, the optional
// attributes' names. The format itself is specified in mesh/solution_format.md.
#include <climits>
#include <cstdint>

namespace radview::solution_format {

inline constexpr int kVersion = 1;
inline constexpr int kArrayBuffer = 34962;         // bufferView.target of vertex attributes
inline constexpr int kElementArrayBuffer = 34963;  // bufferView.target of indices
inline constexpr uint32_t kNoVertex = UINT32_MAX;  // a mesh node not (yet) in a primitive
inline constexpr const char* kGradientAttributes[3] = {"_RADIOSITY_GRADIENT_R", "_RADIOSITY_GRADIENT_G",
                                                       "_RADIOSITY_GRADIENT_B"};
inline constexpr const char* kStandardErrorAttribute = "_RADIOSITY_STANDARD_ERROR";

}  // namespace radview::solution_format
