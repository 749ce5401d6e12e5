#include "import/ply_mesh.h"

#include "core/error.h"
#include "core/limits.h"
#include "import/ply_writer.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace radview {

namespace {

constexpr std::array<std::array<const char*, 3>, 3> kColourNames = {{
    {"red", "green", "blue"},
    {"r", "g", "b"},
    {"diffuse_red", "diffuse_green", "diffuse_blue"},
}};
constexpr const char* kGreyNames[] = {"radiosity", "B"};

std::string propertyList(const PlyElement& element) {
  std::string names;
  for (const PlyProperty& p : element.properties) names += (names.empty() ? "" : " ") + p.name;
  return names.empty() ? "no properties" : names;
}

class PlyMeshBuilder {
 public:
  PlyMeshBuilder(const PlyFile& ply, const std::string& path, const ImportOptions& options)
      : ply_(ply), path_(path), options_(options) {}

  ImportedMesh build() {
    const PlyElement* vertex = ply_.find("vertex");
    if (!vertex || vertex->count == 0) fail("no vertex element: nothing to show");
    checkLimit(path_, vertex->count, kMaxSolutionNodes, "vertices");
    readNodes(*vertex);
    const PlyElement* face = ply_.find("face");
    if (!face || face->count == 0)
      fail("no faces: a point cloud of " + std::to_string(vertex->count) +
           " vertices (radview shows radiosity on surfaces)");
    checkLimit(path_, face->count, kMaxSolutionElements, "faces");
    readFaces(*face);
    if (const PlyElement* edge = ply_.find("edge")) readEdges(*edge);
    for (const PlyElement& e : ply_.elements)
      if (e.name != "vertex" && e.name != "face" && e.name != "edge")
        imported_.warnings.push_back("element " + e.name + " (" + std::to_string(e.count) + ") ignored");
    imported_.mesh.materials = {unknownMaterial()};
    finishImportedMesh(imported_, path_);
    return std::move(imported_);
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw Error(path_, problem); }

  const PlyProperty& scalar(const PlyElement& element, const char* name) const {
    const PlyProperty* p = element.find(name);
    if (!p) fail(element.name + " has no property " + name + " (it has: " + propertyList(element) + ")");
    if (p->isList) fail(element.name + " property " + name + " is a list, not a number");
    return *p;
  }

  // The properties B is read from: three for a colour, one for grey.
  std::vector<const PlyProperty*> valueProperties(const PlyElement& vertex) {
    if (!options_.valueProperty.empty()) return {&scalar(vertex, options_.valueProperty.c_str())};
    for (const auto& names : kColourNames)
      if (vertex.find(names[0]) && vertex.find(names[1]) && vertex.find(names[2]))
        return {&scalar(vertex, names[0]), &scalar(vertex, names[1]), &scalar(vertex, names[2])};
    for (const char* name : kGreyNames)
      if (vertex.find(name)) return {&scalar(vertex, name)};
    const PlyElement* face = ply_.find("face");
    const bool faceColours = face && face->find("red");
    fail("no per-vertex values: the vertex element has " + propertyList(vertex) +
         "; radview reads B from red green blue (or r g b, diffuse_red ...), a scalar named radiosity or B, or one "
         "named with --value-property" +
         (faceColours ? " (this file's colours are per face, one value per face, where radview needs one per vertex)"
                      : ""));
  }

  void readNodes(const PlyElement& vertex) {
    const PlyProperty* xyz[3] = {&scalar(vertex, "x"), &scalar(vertex, "y"), &scalar(vertex, "z")};
    const std::vector<const PlyProperty*> value = valueProperties(vertex);
    bool integer = false;
    for (const PlyProperty* p : value) {
      if (isInteger(p->type) && isSigned(p->type))
        fail("vertex property " + p->name + " is " + toString(p->type) +
             ": radview reads values stored as float, double or unsigned integers");
      integer = integer || isInteger(p->type);
    }
    std::string names;
    for (const PlyProperty* p : value) names += (names.empty() ? "" : " ") + p->name;
    imported_.valueSource = "vertex " + std::string(value.size() == 1 ? "property " : "properties ") + names + " (" +
                            toString(value[0]->type) + (value.size() == 1 ? ", grey" : "") + "), " +
                            conversionName(integer, options_.colours);

    std::vector<Node>& nodes = imported_.mesh.nodes;
    nodes.resize(vertex.count);
    for (size_t i = 0; i < nodes.size(); ++i) {
      Vec3 position;
      for (int k = 0; k < 3; ++k) position[k] = xyz[k]->values[i];
      if (!isFinite(position)) fail("vertex " + std::to_string(i) + ": its position is not finite");
      double b[3];
      for (int k = 0; k < 3; ++k) {
        const PlyProperty& p = *value[value.size() == 1 ? 0 : size_t(k)];
        const double stored = p.values[i];
        if (!std::isfinite(stored))
          fail("vertex " + std::to_string(i) + ": " + p.name + " is " + std::to_string(stored) +
               ", not a finite number");
        b[k] = linearValue(stored, isInteger(p.type) ? integerMax(p.type) : 0.0, options_.colours);
      }
      nodes[i].position = position;
      nodes[i].B = Rgb(b[0], b[1], b[2]);
    }
    readGradients(vertex);
  }

  // The gradients radview's export writes, when all nine properties are there.
  void readGradients(const PlyElement& vertex) {
    std::vector<const PlyProperty*> gradient;
    for (const char* channel : kGradientChannels)
      for (const char* axis : {"x", "y", "z"})
        if (const PlyProperty* p = vertex.find(std::string("gradient_") + channel + "_" + axis); p && !p->isList)
          gradient.push_back(p);
    if (gradient.size() != 9) return;
    std::vector<Node>& nodes = imported_.mesh.nodes;
    for (size_t i = 0; i < nodes.size(); ++i)
      for (size_t c = 0; c < 3; ++c)
        for (size_t k = 0; k < 3; ++k) nodes[i].gradient[c][int(k)] = gradient[3 * c + k]->values[i];
    imported_.mesh.hasGradients = true;  // validateMesh refuses non-finite ones
  }

  const PlyProperty& indexList(const PlyElement& element, const char* const* names, size_t count) const {
    for (size_t n = 0; n < count; ++n)
      if (const PlyProperty* p = element.find(names[n]); p && p->isList) return *p;
    fail(element.name + " has no list " + names[0] + " (it has: " + propertyList(element) + ")");
  }

  uint32_t vertexIndex(double value, const std::string& what) const {
    if (value != std::floor(value)) fail(what + " refers to vertex " + std::to_string(value) + ", not a whole number");
    if (!(value >= 0.0 && value < double(imported_.mesh.nodes.size())))
      fail(what + " refers to vertex " + std::to_string(int64_t(value)) + "; the file has " +
           std::to_string(imported_.mesh.nodes.size()));
    return uint32_t(value);
  }

  void readFaces(const PlyElement& face) {
    const char* names[] = {"vertex_indices", "vertex_index"};
    const PlyProperty& list = indexList(face, names, 2);
    std::vector<Element>& elements = imported_.mesh.elements;
    elements.resize(face.count);
    for (size_t f = 0; f < elements.size(); ++f) {
      const uint64_t begin = list.offsets[f], end = list.offsets[f + 1];
      const std::string what = "face " + std::to_string(f);
      if (end - begin < 3) fail(what + " has " + std::to_string(end - begin) + " vertices (a face needs at least 3)");
      checkLimit(path_, end - begin, kMaxElementCorners, "vertices in " + what);
      std::vector<uint32_t>& corners = elements[f].corners;
      for (uint64_t k = begin; k < end; ++k) corners.push_back(vertexIndex(list.values[k], what));
      std::vector<uint32_t> sorted = corners;
      std::sort(sorted.begin(), sorted.end());
      if (const auto twice = std::adjacent_find(sorted.begin(), sorted.end()); twice != sorted.end())
        fail(what + " uses vertex " + std::to_string(*twice) + " twice");
    }
  }

  void readEdges(const PlyElement& edge) {
    const PlyProperty* continuity = edge.find("continuity");
    if (!continuity || continuity->isList) {
      imported_.warnings.push_back("element edge (" + std::to_string(edge.count) +
                                   ") has no continuity property: its edges are not discontinuities");
      return;
    }
    const PlyProperty& a = scalar(edge, "vertex1");
    const PlyProperty& b = scalar(edge, "vertex2");
    for (size_t i = 0; i < edge.count; ++i) {
      const std::string what = "edge " + std::to_string(i);
      const double order = continuity->values[i];
      if (order != -1.0 && order != 0.0 && order != 1.0)
        fail(what + ": continuity " + std::to_string(order) + " (expected -1, 0 or 1)");
      const uint32_t from = vertexIndex(a.values[i], what), to = vertexIndex(b.values[i], what);
      if (from == to) fail(what + " joins vertex " + std::to_string(from) + " to itself");
      if (order < 1.0) imported_.mesh.discontinuities.push_back({from, to, Continuity(int(order))});
    }
  }

  const PlyFile& ply_;
  const std::string& path_;
  const ImportOptions& options_;
  ImportedMesh imported_;
};

}  // namespace

ImportedMesh plyMesh(const PlyFile& ply, const std::string& path, const ImportOptions& options) {
  return PlyMeshBuilder(ply, path, options).build();
}

ImportedMesh readPlyMesh(const std::string& path, const ImportOptions& options) {
  return plyMesh(readPly(path), path, options);
}

}  // namespace radview
