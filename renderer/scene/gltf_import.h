#pragma once
// glTF 2.0 -> radview's scene model: world-space triangles with a diffuse reflectance and an
// emission each, plus the file's perspective cameras.
#include "scene/gltf_document.h"
#include "scene/scene.h"

#include <string>
#include <vector>

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
Scene importScene(const GltfDocument& document, std::vector<std::string>& warnings);

// The perspective cameras alone, found and checked as importScene does; meshes are not read.
// For solution files, whose meshes are readSolution's (mesh/solution_file.h).
std::vector<SceneCamera> importCameras(const GltfDocument& document, std::vector<std::string>& warnings);

}  // namespace radview
