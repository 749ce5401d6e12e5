#pragma once
// The Bezier pieces of a quadratic or C1 method, built from a mesh for the pass that draws
// them: as vertices for the Bezier pass (tessellated, the radiosity surface, the quadratic
// method per pixel), or streamed into the deferred pass (the C1 methods per pixel). No GL
// calls of its own beyond the passes' uploads.
#include "gl/bezier_pass.h"
#include "gl/deferred_pass.h"
#include "interp/interpolant.h"
#include "interp/surface_triangulation.h"
#include "interp/vertex_gradients.h"
#include "mesh/radiosity_mesh.h"
#include "mesh/topology.h"

#include <glm/glm.hpp>

#include <memory>
#include <vector>

namespace radview::gl {

// What a pass's pieces were built for: a method's pieces in one Clough-Tocher variant, or the
// quadratic method's 6-node triangles alone (drawn per pixel beside Gouraud's triangles and the
// serendipity quads). Passes hold a std::optional of it: none, when they hold nothing.
struct PiecesKey {
  Method method = Method::Flat;
  CloughTocherVariant variant = CloughTocherVariant::AffineInvariant;
  bool quadraticTrianglesOnly = false;
  ThinPlateSettings thinPlate;  // Method::ThinPlate's smoothing (ignored by the others)

  static PiecesKey quadraticTriangles() { return {Method::Quadratic, CloughTocherVariant::AffineInvariant, true, {}}; }
  bool operator==(const PiecesKey& other) const {
    return method == other.method && variant == other.variant &&
           quadraticTrianglesOnly == other.quadraticTrianglesOnly &&
           (method != Method::ThinPlate || thinPlate.lambda == other.thinPlate.lambda);
  }
  bool operator!=(const PiecesKey& other) const { return !(*this == other); }
};

// The pieces as the Bezier pass draws them (which pieces: the method's MethodInfo::gpu; none for a
// method drawn without pieces), and when `split` is given the lines that split
// elements into them (none for quadratic elements).
// `topology` is the mesh's own, shared with the triangulation the pieces are built on.
std::vector<BezierVertex> pieceVertices(const RadiosityMesh& mesh, const std::shared_ptr<const MeshTopology>& topology,
                                        const PiecesKey& key, std::vector<glm::vec3>* split);

// What a C1 method's pieces are built from: the mesh's triangulation and its corner gradients. It needs no OpenGL, so
// that the viewer can make it beside its frame loop; it keeps the mesh it was made from, and the values the pieces
// take (the thin-plate spline's for Method::ThinPlate, else the mesh itself).
struct DeferredSetup {
  std::shared_ptr<const RadiosityMesh> mesh;
  std::shared_ptr<const RadiosityMesh> values;
  PiecesKey piecesKey;
  std::unique_ptr<const SurfaceTriangulation> surface;
  CornerGradients gradients;
  const PiecesKey& key() const { return piecesKey; }
};
DeferredSetup prepareDeferred(std::shared_ptr<const RadiosityMesh> mesh, std::shared_ptr<const MeshTopology> topology,
                              const PiecesKey& key);

// A C1 method's pieces, straight into the deferred pass: each patch built on every core a block
// of triangles at a time and never kept; its split lines into `split` when given.
void uploadDeferred(const DeferredSetup& setup, DeferredPass& pass, std::vector<glm::vec3>* split);

}  // namespace radview::gl
