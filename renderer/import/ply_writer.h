#pragma once
// radview's solutions as PLY, for MeshLab, CloudCompare, Blender and other tools: binary little
// endian; per vertex float x y z and float red green blue (B, linear, unclamped), and where the
// mesh has them the gradients of B as float gradient_red_x ... gradient_blue_z; faces as
// polygons (list uchar uint vertex_indices, uint counts past 255 corners); an `edge` element
// (int vertex1 vertex2, char continuity -1 or 0) for the discontinuity tags. readPlyMesh reads
// it back to the same mesh at float precision.
#include "mesh/radiosity_mesh.h"

#include <string>

namespace radview {

// The channel names of the gradient properties, gradient_<channel>_<x|y|z>.
inline constexpr const char* kGradientChannels[] = {"red", "green", "blue"};

// The file's bytes. Throws Error(source, ...) for a mesh that fails validateMesh or has
// quadratic elements (a PLY face has no mid-edge nodes).
std::string plyBytes(const RadiosityMesh& mesh, const std::string& source);

// Writes plyBytes to `path` through core/atomic_file.h. Throws Error(path, ...).
void writePly(const RadiosityMesh& mesh, const std::string& path);

}  // namespace radview
