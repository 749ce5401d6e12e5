#pragma once
// Shooting patches made of several elements (Cohen, Greenberg, Immel, Brock 1986 take the
// patches first and the elements inside them; a discontinuity mesh gives the elements first).
// A discontinuity mesh cuts polygons into many small triangles along shadow boundaries; were
// each a patch, a solve would shoot once per triangle. Grouping them back into patches of the
// size a uniform mesh would have keeps the shooting cost of the uniform mesh, while the
// receivers (the nodes) keep every discontinuity.
#include "mesh/radiosity_mesh.h"
#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace radview {

// The shooting patch of every element: elements of one scene polygon (Element::surface) and
// one material whose centroids fall in the same cell of a grid laid over the polygon, along
// its longest edge, with cells of about `size` that divide its extent exactly (a rectangle
// gets the cells a uniform mesh of that size would have). Elements of no surface or of a
// degenerate one are patches on their own. Patches are numbered in order of their first
// element. Throws Error for a size that is not positive and finite.
std::vector<uint32_t> groupIntoShootingPatches(const Scene& scene, const RadiosityMesh& mesh, double size);

}  // namespace radview
