#pragma once
// A radiosity mesh made ready for MeshRenderer without OpenGL: moved near the origin, its
// T-vertices repaired when asked, its topology and display triangles built. That is the part of
// opening a mesh that takes seconds at 10^6 elements, so the viewer does it beside its frame
// loop and then only uploads (MeshRenderer::adoptMesh).
#include "core/types.h"
#include "mesh/display_mesh.h"
#include "mesh/radiosity_mesh.h"
#include "mesh/topology.h"

#include <memory>

namespace radview::gl {

struct PreparedMesh {
  std::shared_ptr<const RadiosityMesh> original;  // as given
  std::shared_ptr<const RadiosityMesh> drawn;     // repaired when asked, moved by -origin
  std::shared_ptr<const MeshTopology> topology;   // drawn's, shared with every method's pieces
  DisplayMesh display;                            // drawn's
  // display.triangles' first vertices: the elements the quadratic method interpolates linearly,
  // which it draws per pixel as Gouraud's triangles (MeshRenderer::isQuadraticPerPixel).
  size_t linearForQuadraticVertices = 0;
  Vec3 origin{0.0};
  bool repairedTVertices = false;
  double brightestLuminance = 1.0;  // of the non-emitting elements' nodes, for the surface view
};

// Throws Error for a mesh that cannot be drawn (a discontinuity edge that is no element edge).
PreparedMesh prepareMesh(std::shared_ptr<const RadiosityMesh> original, bool repairTVertices);

}  // namespace radview::gl
