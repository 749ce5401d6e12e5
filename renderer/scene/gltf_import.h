#pragma once
// glTF 2.0 -> radview's scene model: world-space triangles with a diffuse reflectance and an
// emission each, plus the file's perspective cameras.
#include "scene/gltf_document.h"
#include "scene/scene.h"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace tinygltf {
struct Primitive;
}

namespace radview {

// Walks the default scene's node hierarchy (every root node when the file names no default
// scene), applying each node's matrix or TRS. Triangle primitives (TRIANGLES, TRIANGLE_STRIP,
// TRIANGLE_FAN, indexed or not) become one Polygon per triangle, counter-clockwise seen from
// its front (a mirroring transform flips the winding back). Materials: rho = baseColorFactor
// rgb clamped to [0,1]; E = emissiveFactor * KHR_materials_emissive_strength; a primitive
// without a material gets glTF's default (rho 1, E 0). Perspective cameras on nodes become
// SceneCameras looking down the node's -Z with +Y up.
//
// Appends to `warnings` what was skipped or ignored (points and lines, degenerate triangles,
// animations, ...). Throws Error(document.path(), ...) for anything radview would have to
// guess about, and "no triangles to show" when nothing drawable remains.
//
// `visit`, when given, is called for every triangle primitive imported, with what the scene
// keeps of it and the primitive itself, for a reader that wants more (import/gltf_colour_mesh.h).
struct ImportedPrimitive {
  const tinygltf::Primitive& primitive;
  const std::string& what;                                // "mesh 0 primitive 1", for messages
  const std::vector<Vec3>& positions;                     // the primitive's vertices, world space
  const std::vector<std::array<uint32_t, 3>>& triangles;  // counter-clockwise, degenerate ones left out
  int material;                                           // index into the scene's materials
};
using PrimitiveVisitor = std::function<void(const ImportedPrimitive&)>;
// Where a primitive has COLOR_0, each triangle's rho is its material's times the mean COLOR_0 of
// its corners (glTF: COLOR_0 multiplies the base colour; radview's polygons have one rho each),
// unless `colourModulatesRho` is false (the file is read for COLOR_0 as radiosity instead).
Scene importScene(const GltfDocument& document, std::vector<std::string>& warnings, const PrimitiveVisitor& visit = {},
                  bool colourModulatesRho = true);

// A primitive's COLOR_0 as rgb (alpha dropped), one per vertex, as stored: VEC3 or VEC4 of
// float or normalized unsigned byte or short (glTF 2.0, "Meshes"; linear). Empty when the
// primitive has none. `integer` tells whether the stored values were integers. Throws
// Error(document.path(), "<what> COLOR_0: ...") for another type or count.
std::vector<Rgb> readVertexColours(const GltfDocument& document, const tinygltf::Primitive& primitive,
                                   const std::string& what, size_t vertexCount, bool* integer = nullptr);

// The perspective cameras alone, found and checked as importScene does; meshes are not read.
// For solution files, whose meshes are readSolution's (mesh/solution_file.h).
std::vector<SceneCamera> importCameras(const GltfDocument& document, std::vector<std::string>& warnings);

}  // namespace radview
