#pragma once
// A uniform mesh made to follow the lines where polygons touch (Heckbert 1992's D0
// discontinuities: a block standing on the floor), and rid of what lies inside closed solids.
// An element that straddles a block's footprint has nodes under the block, where nothing
// reaches, and nodes in the light: the mean of its nodes is neither what its lit part receives
// nor what it reflects, and the part under the block shoots into the block (light and shadow
// leaks: Baum, Rushmeier, Winget 1989). Cut along the footprint, each piece is wholly lit or
// wholly hidden.
#include "mesh/radiosity_mesh.h"
#include "scene/scene.h"

namespace radview {

// `mesh` (of `scene`, meshUniformly's contract) with every element cut along the lines of the
// D0 contact segments on its polygon (findContacts) that pass through it, each a
// full cut of the convex element by the segment's line, and the elements (cut or not) whose
// centroid is hidden left out: those from which a ray along the normal first meets a surface
// from behind (the floor under a block, the ceiling behind the light). A cut point on an edge
// is one node for both elements that share the edge and are cut by the same line, and a
// T-vertex on a neighbour that is not. Nodes no element uses are removed. Elements must be
// convex (a uniform mesh's are).
RadiosityMesh cutAtContacts(const Scene& scene, RadiosityMesh mesh);

}  // namespace radview
