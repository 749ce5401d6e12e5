#pragma once
// radview's solution files: a radiosity mesh stored as a conformant glTF 2.0 file (.glb, or
// .gltf with the buffer embedded), so that any glTF viewer shows the shaded result, while the
// RADVIEW_radiosity_mesh extension keeps what glTF cannot say (polygonal and quadratic
// elements, node identity, discontinuity edges). The format is specified in
// mesh/solution_format.md.
#include "mesh/radiosity_mesh.h"
#include "scene/gltf_document.h"

#include <string>
#include <vector>

namespace radview {

// The name of the extension on the root, the materials and the primitives.
inline constexpr const char* kSolutionExtension = "RADVIEW_radiosity_mesh";

// Writes `mesh` to `path`: binary glTF for .glb, JSON with a data: URI buffer for .gltf, with
// `cameras` (the scene's, usually) as standard glTF perspective cameras, which loadFile reads
// back. Throws Error(path, ...) if the mesh fails validateMesh, has no element, has a value
// that does not fit in float32, a camera makes no view, or the file cannot be written (then
// any file that was at `path` is left unchanged: core/atomic_file.h).
void writeSolution(const RadiosityMesh& mesh, const std::string& path, const std::vector<SceneCamera>& cameras = {});

// True when the document carries the root RADVIEW_radiosity_mesh extension.
bool isSolution(const GltfDocument& document);

// Reads a solution back. Every accessor goes through the document's validated reader and
// every count, offset and index of the extension is checked before use; the result passes
// validateMesh. Positions, B and gradients come back at float32 precision. Throws
// Error(document.path(), ...) naming the first inconsistency.
RadiosityMesh readSolution(const GltfDocument& document);

// The display tone map of COLOR_0 is clamp(B * scale, 0, 1) per channel, with this scale:
// 0.8 / the 99th percentile of the Rec. 709 luminance of the nodes of non-emitting elements
// (of all nodes if every element emits), or 0.8 / the largest luminance when that percentile
// is 0, or 1 for an all-black mesh.
double toneMapScale(const RadiosityMesh& mesh);

}  // namespace radview
