#pragma once
// A radiosity mesh made ready for MeshRenderer without OpenGL: moved near the origin, its
// T-vertices repaired when asked, its topology and overlays built, and its triangles when asked.
// That is the part of opening a mesh that takes seconds at 10^6 elements, so the viewer does it
// beside its frame loop and then only uploads (MeshRenderer::adoptMesh).
#include "core/types.h"
#include "mesh/display_mesh.h"
#include "mesh/radiosity_mesh.h"
#include "mesh/topology.h"

#include <memory>
#include <optional>
#include <vector>

namespace radview::gl {

// The triangles flat shading, Gouraud and the polygon methods draw (displayTriangles), those of
// the elements the quadratic method interpolates linearly first: it draws per pixel the first
// linearForQuadraticVertices as Gouraud's triangles (MeshRenderer::isQuadraticPerPixel).
struct DrawnTriangles {
  std::vector<DisplayVertex> vertices;
  size_t linearForQuadraticVertices = 0;
};
DrawnTriangles drawnTriangles(const RadiosityMesh& drawn, const MeshTopology& topology);

struct PreparedMesh {
  std::shared_ptr<const RadiosityMesh> original;  // as given
  std::shared_ptr<const RadiosityMesh> drawn;     // repaired when asked, moved by -origin
  std::shared_ptr<const MeshTopology> topology;   // drawn's (of its positions before the move), shared with every method's pieces
  DisplayMesh display;                            // drawn's overlays
  bool elementEdges = true;                       // display.elementEdges built (PrepareOptions::elementEdges)
  // drawn's triangles, when asked for; else MeshRenderer builds them when a method first draws
  // them (a C1 method per pixel never does: a second or more, and 264 MB, at 10^6 elements).
  std::optional<DrawnTriangles> triangles;
  Vec3 origin{0.0};
  bool repairedTVertices = false;
  double brightestLuminance = 1.0;  // of the non-emitting elements' nodes, for the surface view
};

struct PrepareOptions {
  bool repairTVertices = false;
  bool triangles = false;    // the display triangles now, not when a method first draws them
  bool elementEdges = true;  // false: the caller keeps the lines it has (a continuity edit changes none)
  // The original's topology (MeshTopology(*original)), where the caller has it: not built again,
  // unless the T-vertices are repaired.
  std::shared_ptr<const MeshTopology> topology;
};

// Throws Error for a mesh that cannot be drawn (a discontinuity edge that is no element edge).
PreparedMesh prepareMesh(std::shared_ptr<const RadiosityMesh> original, const PrepareOptions& options);

}  // namespace radview::gl
