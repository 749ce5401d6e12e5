#pragma once
// Undoing glTF's triangulation: glTF stores every quad as two triangles. Pairs that form a flat
// convex quad are merged back, so that quads mesh into quad elements and C&W §9.2's figs.
// 9.7-9.8 (Gouraud shading of a quad depends on its orientation) show on real quads.
#include "scene/scene.h"

namespace radview {

// Returns the scene with pairs of triangles merged into quads and every other polygon as it
// was (a merged quad takes the place of its lower-indexed triangle). Two triangles merge when
//  1. they share an edge, its end positions equal within relativeTolerance * the scene's
//     bounding diagonal, traversed in opposite directions (so both face the same way);
//  2. they have the same material;
//  3. they are coplanar: each one's far vertex lies within relativeTolerance * the quad's
//     size of the other's plane;
//  4. their union is a strictly convex quad;
//  5. the match is mutual: each is the other's preferred partner, the neighbour satisfying
//     1-4 across its longest edge (for a triangulated quad, the diagonal), ties going to the
//     lower polygon index.
// The quad keeps the triangles' orientation and starts at the first vertex of the lower-indexed
// triangle. The outcome depends on the geometry only, not on how each triangle's vertex list
// is rotated, and on polygon order only through exact ties in rule 5.
Scene mergeTrianglesIntoQuads(const Scene& scene, double relativeTolerance = 1e-6);

}  // namespace radview
