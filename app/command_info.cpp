#include "app/commands.h"
#include "geom/polygon.h"
#include "mesh/standard_errors.h"
#include "mesh/topology.h"
#include "solve/viewed_file.h"

#include <cstdio>
#include <iostream>
#include <map>

namespace radview {

namespace {

const char* shapeName(size_t corners, bool convex) {
  if (corners == 3) return "triangles";
  if (corners == 4 && convex) return "quads";
  return convex ? "other convex" : "concave";
}

void printShapes(const std::map<std::string, size_t>& byShape) {
  bool first = true;
  std::cout << " (";
  for (const auto& [shape, count] : byShape) {
    std::cout << (first ? "" : ", ") << shape << ' ' << count;
    first = false;
  }
  std::cout << ')';
}

void printMesh(const RadiosityMesh& mesh) {
  std::map<std::string, size_t> byShape;
  size_t linear = 0, quadratic = 0, emitting = 0;
  for (size_t e = 0; e < mesh.elements.size(); ++e) {
    const Element& element = mesh.elements[e];
    byShape[shapeName(element.corners.size(), isConvex(mesh.cornerPositions(e)))]++;
    (element.order() == ElementOrder::Linear ? linear : quadratic)++;
    if (mesh.materials[element.material].isEmitter()) ++emitting;
  }
  const MeshTopology topology(mesh);
  std::cout << "nodes: " << mesh.nodes.size() << (mesh.hasGradients ? " (with gradients)" : "") << '\n';
  std::cout << "elements: " << mesh.elements.size();
  printShapes(byShape);
  std::cout << "; linear " << linear << ", quadratic " << quadratic << "; emitting " << emitting << '\n';
  std::cout << "T-vertices: " << topology.tVertices().size() << '\n';
  // Edges, each once, by the continuity the file tags them with (an edge tagged C1 is
  // indistinguishable from an untagged one, so only the discontinuities are counted).
  std::cout << "discontinuity edges: " << toString(Continuity::Cm1) << ' ' << topology.countEdges(Continuity::Cm1)
            << ", " << toString(Continuity::C0) << ' ' << topology.countEdges(Continuity::C0) << '\n';
  if (!mesh.hasStandardErrors) return;
  const StandardErrorSummary errors = summariseStandardErrors(mesh);
  std::cout << "standard errors (luminance, " << errors.nodes << " nodes of lit surfaces, mean B " << errors.meanB
            << "): median " << errors.median << ", 99th percentile " << errors.p99 << ", largest " << errors.largest
            << "; " << errors.uncertain << " nodes above 0\n";
}

}  // namespace

int runInfo(const InfoOptions& options) {
  const ViewedFile viewed = openForViewing(options.file, options.elementSize, options.import, kDirectLight);
  const LoadedFile& file = viewed.file;
  std::cout << "file: " << file.path << (file.isSolution ? " (radiosity solution)" : " (scene)") << '\n';
  if (!file.isSolution) {
    const Scene& scene = file.scene;
    std::map<std::string, size_t> byShape;
    for (const Polygon& p : scene.polygons) byShape[shapeName(p.vertices.size(), isConvex(p.vertices))]++;
    std::cout << "polygons: " << scene.polygons.size();
    printShapes(byShape);
    std::cout << '\n';
    const std::vector<int> emitters = scene.emitters();
    double emitterArea = 0.0;
    for (int i : emitters) emitterArea += area(scene.polygons[i].vertices);
    std::cout << "emitters: " << emitters.size() << " polygons, area " << emitterArea << '\n';
    std::cout << "materials: " << scene.materials.size() << '\n';
    for (const Material& m : scene.materials) std::cout << "  " << m << '\n';
    std::cout << "cameras: " << scene.cameras.size() << '\n';
    std::cout << "bounds: " << scene.bounds() << '\n';
    std::cout << "-- uniform mesh, element size " << viewed.elementSize << ", lit directly by the emitters:\n";
  } else {
    std::cout << "materials: " << viewed.mesh.materials.size() << '\n';
    for (const Material& m : viewed.mesh.materials) std::cout << "  " << m << '\n';
    std::cout << "cameras: " << file.scene.cameras.size() << '\n';
    std::cout << "bounds: " << viewed.mesh.bounds() << '\n';
    if (!file.valueSource.empty()) std::cout << "B from: " << file.valueSource << '\n';
    if (!file.gatherRefusal.empty()) std::cout << "final gather: not available (" << file.gatherRefusal << ")\n";
  }
  printMesh(viewed.mesh);
  for (const std::string& w : file.warnings) std::cout << "warning: " << w << '\n';
  return 0;
}

}  // namespace radview
