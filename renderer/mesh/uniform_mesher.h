#pragma once
// The first mesh of a scene, and the mesh of a `--direct-only` preview: every polygon meshed
// uniformly into elements of a chosen size, quads into quads and triangles into triangles.
#include "core/limits.h"
#include "mesh/radiosity_mesh.h"
#include "scene/scene.h"

#include <cstddef>

namespace radview {

// Meshes every polygon on its own, into linear elements with edges of at most about
// elementSize:
//  - a strictly convex, planar (within 1e-4 of its size) quad: an n x m grid of quads, by
//    bilinear subdivision, n and m = ceil(longer of each pair of opposite edges / size);
//  - a triangle: regular subdivision into n^2 triangles, n = ceil(longest edge / size);
//  - any other polygon (a warped quad included): triangulatePolygon, then every triangle
//    subdivided as above with one n for the whole polygon, so that the pieces conform.
// Nodes are shared between the elements of one polygon, never across polygons; B is zero.
// Element.surface is the polygon's index, Element.material its material; the mesh's materials
// are the scene's. Zero-area polygons get no elements (they receive and emit nothing).
// Throws Error for a size that is not positive and finite, a self-intersecting polygon, or
// more than kMaxMeshElements elements (naming a size that fits).
RadiosityMesh meshUniformly(const Scene& scene, double elementSize);

}  // namespace radview
