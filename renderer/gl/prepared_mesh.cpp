#include "gl/prepared_mesh.h"

#include "interp/interpolant.h"
#include "interp/t_vertex_repair.h"

#include <algorithm>
#include <vector>

namespace radview::gl {

namespace {

// Orders the triangles so that those of the elements the quadratic method interpolates
// linearly come first, and returns how many vertices they take.
size_t orderLinearForQuadraticFirst(const RadiosityMesh& mesh, std::vector<DisplayVertex>& triangles) {
  auto linear = [&](uint32_t e) { return !isQuadraticTriangle(mesh.elements[e]) && !isSerendipityQuad(mesh, e); };
  bool allLinear = true;
  for (size_t v = 0; v < triangles.size() && allLinear; v += 3) allLinear = linear(triangles[v].element);
  if (allLinear) return triangles.size();  // in order already
  std::vector<DisplayVertex> ordered;
  ordered.reserve(triangles.size());
  size_t linearVertices = 0;
  for (bool first : {true, false})
    for (size_t v = 0; v < triangles.size(); v += 3)
      if (linear(triangles[v].element) == first) {
        ordered.insert(ordered.end(), triangles.begin() + ptrdiff_t(v), triangles.begin() + ptrdiff_t(v + 3));
        if (first) linearVertices += 3;
      }
  triangles = std::move(ordered);
  return linearVertices;
}

}  // namespace

DrawnTriangles drawnTriangles(const RadiosityMesh& drawn, const MeshTopology& topology) {
  DrawnTriangles triangles;
  triangles.vertices = displayTriangles(drawn, topology);
  triangles.linearForQuadraticVertices = orderLinearForQuadraticFirst(drawn, triangles.vertices);
  return triangles;
}

PreparedMesh prepareMesh(std::shared_ptr<const RadiosityMesh> original, const PrepareOptions& options) {
  const bool repairTVertices = options.repairTVertices;
  RadiosityMesh mesh = repairTVertices ? radview::repairTVertices(*original) : *original;
  PreparedMesh prepared;
  // Of the mesh as given (or repaired), before it moves: the topology the CPU's interpolants and
  // the continuity editor build, which the editor can then hand over.
  prepared.topology = options.topology && !repairTVertices ? options.topology
                                                           : std::make_shared<const MeshTopology>(mesh);
  // The GPU draws in float32, which resolves only 0.0078 at 1e5 from the origin: a scene there
  // 1e-3 across collapsed to a few points (tests/gl/extremes_render_test.cpp). Its coordinates
  // are taken relative to the mesh's centre, in double, before anything becomes float, and
  // MeshRenderer::render moves the camera's matrix by the same (camera-relative rendering).
  prepared.origin = mesh.bounds().center();
  for (Node& node : mesh.nodes) node.position -= prepared.origin;
  prepared.display = buildDisplayMesh(mesh, *prepared.topology, options.elementEdges);
  prepared.elementEdges = options.elementEdges;
  if (options.triangles) prepared.triangles = drawnTriangles(mesh, *prepared.topology);
  double brightest = 0.0;
  for (const Element& e : mesh.elements)
    if (!mesh.materials[e.material].isEmitter())
      for (uint32_t n : e.corners)
        brightest = std::max(brightest, glm::dot(mesh.nodes[n].B, Rgb(0.2126, 0.7152, 0.0722)));
  prepared.brightestLuminance = brightest > 0.0 ? brightest : 1.0;
  prepared.drawn = std::make_shared<const RadiosityMesh>(std::move(mesh));
  prepared.original = std::move(original);
  prepared.repairedTVertices = repairTVertices;
  return prepared;
}

}  // namespace radview::gl
