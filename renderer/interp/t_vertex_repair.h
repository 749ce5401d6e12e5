#pragma once
// T-vertex repair at render time (C&W §9.2, after Baum et al.): every element that has a
// neighbour's node on one of its edges is cut into triangles that include that node, so
// Gouraud shading no longer jumps across the edge and is orientation invariant there.
#include "mesh/radiosity_mesh.h"

namespace radview {

// The mesh with each element containing a T-vertex replaced by the triangles of its
// T-vertex-inserted triangulation (SurfaceTriangulation), linear; other elements, nodes,
// materials and discontinuity edges unchanged. `repaired` counts the elements replaced.
RadiosityMesh repairTVertices(const RadiosityMesh& mesh, size_t* repaired = nullptr);

}  // namespace radview
