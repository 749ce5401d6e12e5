#include "gl/method_pieces.h"

#include "core/error.h"
#include "core/parallel_for.h"
#include "gl/patch_nets.h"
#include "gl/patch_vertices.h"
#include "interp/c1_patches.h"

#include <optional>

namespace radview::gl {

namespace {

// The values a method's pieces interpolate: the thin-plate spline's fit for Method::ThinPlate
// (its gradients then estimated from the fit), else the mesh's own.
std::shared_ptr<const RadiosityMesh> pieceValues(std::shared_ptr<const RadiosityMesh> mesh,
                                                 const MeshTopology& topology, const PiecesKey& key) {
  if (key.method != Method::ThinPlate) return mesh;
  return std::make_shared<const RadiosityMesh>(smoothThinPlate(*mesh, topology, key.thinPlate));
}

}  // namespace

std::vector<BezierVertex> pieceVertices(const RadiosityMesh& drawn, const std::shared_ptr<const MeshTopology>& topology,
                                        const PiecesKey& key, std::vector<glm::vec3>* split) {
  std::optional<RadiosityMesh> smoothed;  // the values, as pieceValues
  if (key.method == Method::ThinPlate) smoothed = smoothThinPlate(drawn, *topology, key.thinPlate);
  const RadiosityMesh& mesh = smoothed ? *smoothed : drawn;
  const CloughTocherVariant variant = key.variant;
  switch (methodInfo(key.method).gpu) {
    case GpuPass::Triangles:
    case GpuPass::ScanlinePolygons:
    case GpuPass::BilinearPolygons:
      return {};
    case GpuPass::LagrangePieces:
      return quadraticLagrangeVertices(mesh, *topology);  // its serendipity quads last
    case GpuPass::PowellSabinPieces: {
      const SurfaceTriangulation surface(mesh, topology);
      const auto patches = buildPowellSabinPatches(surface, vertexGradients(surface, true));
      if (split) *split = splitLines(patches, kPowellSabinSplitPoints);
      return powellSabinVertices(patches);
    }
    case GpuPass::CloughTocherPieces: {
      const SurfaceTriangulation surface(mesh, topology);
      const auto patches = buildCloughTocherPatches(surface, vertexGradients(surface, true), variant);
      if (split) *split = splitLines(patches, kCloughTocherSplitPoints);
      return cloughTocherVertices(patches);
    }
  }
  return {};
}

namespace {

// Element triangle by element triangle, make(t)'s patch into the deferred pass.
template <typename MakePatch>
void streamPatches(DeferredPass& pass, size_t triangles, int degree, size_t splitPoints, const MakePatch& make,
                   std::vector<glm::vec3>* split) {
  if (split) split->assign(splitPoints * triangles, glm::vec3(0.0f));
  pass.upload(triangles, degree, [&](glm::vec3* corners, glm::vec4* nets) {
    parallelFor(triangles, [&](size_t t) {
      const auto patch = make(uint32_t(t));
      writeNet(patch, corners + 3 * t, nets + kNetVec4s * t);
      if (split) writeSplitLines(patch, &(*split)[splitPoints * t]);
    });
  });
}

}  // namespace

DeferredSetup prepareDeferred(std::shared_ptr<const RadiosityMesh> mesh, std::shared_ptr<const MeshTopology> topology,
                              const PiecesKey& key) {
  DeferredSetup setup;
  setup.mesh = std::move(mesh);
  setup.values = pieceValues(setup.mesh, *topology, key);
  setup.piecesKey = key;
  setup.surface = std::make_unique<const SurfaceTriangulation>(*setup.values, std::move(topology));
  setup.gradients = vertexGradients(*setup.surface, true);
  return setup;
}

void uploadDeferred(const DeferredSetup& setup, DeferredPass& pass, std::vector<glm::vec3>* split) {
  const SurfaceTriangulation& surface = *setup.surface;
  const size_t triangles = surface.triangles().size();
  const PiecesKey& key = setup.key();
  switch (methodInfo(key.method).gpu) {
    case GpuPass::Triangles:
    case GpuPass::ScanlinePolygons:
    case GpuPass::BilinearPolygons:
    case GpuPass::LagrangePieces:
      throw Error("the deferred pass resolves Bezier pieces: " + methodName(key.method) + " has none to resolve");
    case GpuPass::PowellSabinPieces:
      streamPatches(
          pass, triangles, 2, kPowellSabinSplitPoints,
          [&](uint32_t t) { return powellSabinPatch(surface, setup.gradients, t); }, split);
      break;
    case GpuPass::CloughTocherPieces:
      streamPatches(
          pass, triangles, 3, kCloughTocherSplitPoints,
          [&](uint32_t t) { return cloughTocherPatch(surface, setup.gradients, key.variant, t); }, split);
      break;
  }
}

}  // namespace radview::gl
