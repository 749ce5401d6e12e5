// Reading radview's solution files back (mesh/solution_file.h): every count, offset and index
// of the extension is checked before use, every accessor read through the document's validated
// reader.
#include "mesh/solution_file.h"

#include "core/error.h"
#include "core/limits.h"
#include "mesh/solution_format.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>

namespace radview {

namespace {

using namespace solution_format;

// One primitive's share of the mesh, read and checked on its own, in the primitive's vertex
// numbering.
struct StoredPrimitive {
  std::string what;  // "mesh 0 primitive 1", for messages
  int material = 0;
  std::vector<Node> vertices;
  std::vector<uint32_t> node;     // mesh node of each vertex
  std::vector<uint32_t> element;  // mesh element of each element
  std::vector<Element> elements;  // corners and mid-edge nodes as vertex indices
};

class SolutionReader {
 public:
  explicit SolutionReader(const GltfDocument& document) : doc_(document), model_(document.model()) {}

  RadiosityMesh read() {
    const auto root = model_.extensions.find(kSolutionExtension);
    if (root == model_.extensions.end() || !root->second.IsObject())
      fail(std::string("the root has no ") + kSolutionExtension + " object: not a radview solution file");
    const tinygltf::Value& ext = root->second;
    const int version = integer(ext, "version", kSolutionExtension);
    if (version != kVersion)
      fail(std::string(kSolutionExtension) + " version " + std::to_string(version) +
           " is not supported (this radview reads version " + std::to_string(kVersion) + ")");
    const uint64_t nodeCount = uint64_t(integer(ext, "nodeCount", kSolutionExtension));
    const uint64_t elementCount = uint64_t(integer(ext, "elementCount", kSolutionExtension));
    checkLimit(doc_.path(), nodeCount, kMaxSolutionNodes, "nodes (" + std::string(kSolutionExtension) + ".nodeCount)");
    checkLimit(doc_.path(), elementCount, kMaxSolutionElements,
               "elements (" + std::string(kSolutionExtension) + ".elementCount)");
    if (!ext.Has("hasGradients") || !ext.Get("hasGradients").IsBool())
      fail(std::string(kSolutionExtension) + ": hasGradients is not a boolean");
    mesh_.hasGradients = ext.Get("hasGradients").Get<bool>();
    // Optional: files written before the solver estimated standard errors lack it.
    if (ext.Has("hasStandardErrors")) {
      if (!ext.Get("hasStandardErrors").IsBool())
        fail(std::string(kSolutionExtension) + ": hasStandardErrors is not a boolean");
      mesh_.hasStandardErrors = ext.Get("hasStandardErrors").Get<bool>();
    }
    for (size_t m = 0; m < model_.materials.size(); ++m) mesh_.materials.push_back(material(m));

    // Everything is read (and so bounded by the file's bytes) before nodeCount and
    // elementCount, mere JSON numbers, decide an allocation.
    std::vector<StoredPrimitive> primitives;
    uint64_t vertices = 0, elements = 0;
    for (size_t m = 0; m < model_.meshes.size(); ++m)
      for (size_t p = 0; p < model_.meshes[m].primitives.size(); ++p) {
        primitives.push_back(readPrimitive(model_.meshes[m].primitives[p],
                                           "mesh " + std::to_string(m) + " primitive " + std::to_string(p), nodeCount,
                                           elementCount));
        vertices += primitives.back().vertices.size();
        elements += primitives.back().elements.size();
        // Primitives may share accessors, so a small file could list the same data many times.
        checkLimit(doc_.path(), vertices, kMaxStoredVertices, "vertices in the primitives");
        checkLimit(doc_.path(), elements, kMaxSolutionElements, "elements in the primitives");
      }
    if (nodeCount > vertices)
      fail(std::string(kSolutionExtension) + ": nodeCount " + std::to_string(nodeCount) +
           " is more than the primitives store (" + std::to_string(vertices) + " vertices)");
    if (elementCount == 0) fail(std::string(kSolutionExtension) + ": the solution has no elements");
    if (elementCount != elements)  // with each stored once (see assemble), every element is there
      fail(std::string(kSolutionExtension) + ": elementCount " + std::to_string(elementCount) +
           " differs from the primitives' total of " + std::to_string(elements));
    assemble(primitives, nodeCount, elementCount);
    readDiscontinuities(ext);
    validateMesh(mesh_, doc_.path());
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw Error(doc_.path(), problem); }

  // A non-negative integer property that fits in an int.
  int integer(const tinygltf::Value& object, const char* key, const std::string& where) const {
    if (!object.Has(key)) fail(where + ": " + key + " is missing");
    const tinygltf::Value& v = object.Get(key);
    const double d = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
    if (!(d >= 0.0 && d <= double(INT_MAX) && d == std::floor(d)))
      fail(where + ": " + key + " is not an integer in [0, " + std::to_string(INT_MAX) + "]");
    return int(d);
  }

  Rgb rgb(const tinygltf::Value& object, const char* key, const std::string& where) const {
    const tinygltf::Value* v = object.Has(key) ? &object.Get(key) : nullptr;
    if (v == nullptr || !v->IsArray() || v->ArrayLen() != 3) fail(where + ": " + key + " is not 3 numbers");
    Rgb out;
    for (int c = 0; c < 3; ++c) {
      const tinygltf::Value& x = v->Get(c);
      if (!x.IsNumber() || !std::isfinite(x.GetNumberAsDouble())) fail(where + ": " + key + " is not 3 finite numbers");
      out[c] = x.GetNumberAsDouble();
    }
    return out;
  }

  Material material(size_t index) const {
    const tinygltf::Material& m = model_.materials[index];
    const std::string where = "material " + std::to_string(index) + " " + kSolutionExtension;
    const auto ext = m.extensions.find(kSolutionExtension);
    if (ext == m.extensions.end() || !ext->second.IsObject()) fail(where + " is missing");
    return {m.name, rgb(ext->second, "rho", where), rgb(ext->second, "E", where)};
  }

  std::vector<Vec3> attribute(const tinygltf::Primitive& p, const std::string& name, const std::string& what,
                              size_t count) const {
    const auto it = p.attributes.find(name);
    if (it == p.attributes.end()) fail(what + " has no " + name + " attribute");
    std::vector<Vec3> values = doc_.readVec3(it->second, {what + " " + name, 3, kFloat, false});
    if (count != SIZE_MAX && values.size() != count)
      fail(what + " " + name + " has " + std::to_string(values.size()) + " elements, POSITION has " +
           std::to_string(count));
    return values;
  }

  StoredPrimitive readPrimitive(const tinygltf::Primitive& p, const std::string& what, uint64_t nodeCount,
                                uint64_t elementCount) const {
    const auto found = p.extensions.find(kSolutionExtension);
    if (found == p.extensions.end() || !found->second.IsObject())
      fail(what + " has no " + kSolutionExtension + " object");
    const tinygltf::Value& ext = found->second;
    const std::string extWhat = what + " " + kSolutionExtension;
    if (p.material < 0 || size_t(p.material) >= mesh_.materials.size())
      fail(what + ": material " + std::to_string(p.material) + " does not exist (the file has " +
           std::to_string(mesh_.materials.size()) + " materials)");
    StoredPrimitive out;
    out.what = what;
    out.material = p.material;

    const std::vector<Vec3> positions = attribute(p, "POSITION", what, SIZE_MAX);
    const size_t vertexCount = positions.size();
    const std::vector<Vec3> B = attribute(p, "_RADIOSITY", what, vertexCount);
    std::array<std::vector<Vec3>, 3> gradients;
    if (mesh_.hasGradients)
      for (int c = 0; c < 3; ++c) gradients[size_t(c)] = attribute(p, kGradientAttributes[c], what, vertexCount);
    const std::vector<Vec3> standardErrors =
        mesh_.hasStandardErrors ? attribute(p, kStandardErrorAttribute, what, vertexCount) : std::vector<Vec3>{};
    out.vertices.resize(vertexCount);
    for (size_t v = 0; v < vertexCount; ++v) {
      out.vertices[v].position = positions[v];
      out.vertices[v].B = B[v];
      if (mesh_.hasGradients)
        for (size_t c = 0; c < 3; ++c) out.vertices[v].gradient[c] = gradients[c][v];
      if (mesh_.hasStandardErrors) out.vertices[v].standardError = standardErrors[v];
    }

    auto readList = [&](const char* key, uint64_t limit) {
      return doc_.readUnsigned(integer(ext, key, extWhat), extWhat + "." + key, limit);
    };
    auto checkCount = [&](const char* key, size_t actual, size_t expected) {
      if (actual != expected)
        fail(extWhat + "." + key + " has " + std::to_string(actual) + " elements, expected " +
             std::to_string(expected));
    };
    out.node = readList("node", nodeCount);
    checkCount("node", out.node.size(), vertexCount);
    out.element = readList("element", elementCount);
    const size_t count = out.element.size();
    const std::vector<uint32_t> corners = readList("corners", vertexCount);
    const std::vector<uint32_t> offsets = readList("cornerOffsets", uint64_t(corners.size()) + 1);
    checkCount("cornerOffsets", offsets.size(), count + 1);
    if (offsets.front() != 0 || offsets.back() != corners.size())
      fail(extWhat + ".cornerOffsets must start at 0 and end at the corner count " + std::to_string(corners.size()));
    const std::vector<double> orders =
        doc_.readAccessor(integer(ext, "order", extWhat), {extWhat + ".order", 1, kUnsignedByte, false});
    checkCount("order", orders.size(), count);
    const std::vector<uint32_t> surfaces = readList("surface", uint64_t(INT_MAX) + 1);
    checkCount("surface", surfaces.size(), count);

    size_t midEdgeCount = 0;
    for (size_t k = 0; k < count; ++k) {
      if (offsets[k + 1] < offsets[k] + 3)
        fail(extWhat + ".cornerOffsets: element " + std::to_string(k) + " spans offsets " + std::to_string(offsets[k]) +
             " -> " + std::to_string(offsets[k + 1]) + "; they must increase by at least 3 per element");
      if (offsets[k + 1] - offsets[k] > kMaxElementCorners)
        fail(extWhat + ".cornerOffsets: element " + std::to_string(k) + " has " +
             std::to_string(offsets[k + 1] - offsets[k]) + " corners, more than radview's limit of " +
             std::to_string(kMaxElementCorners));
      if (orders[k] != 1.0 && orders[k] != 2.0)
        fail(extWhat + ".order: element " + std::to_string(k) + " has order " + std::to_string(int(orders[k])) +
             " (expected 1 or 2)");
      if (orders[k] == 2.0) midEdgeCount += offsets[k + 1] - offsets[k];
    }
    std::vector<uint32_t> midEdges;
    if (midEdgeCount > 0 || ext.Has("midEdges")) {
      midEdges = readList("midEdges", vertexCount);
      checkCount("midEdges", midEdges.size(), midEdgeCount);
    }

    size_t nextMidEdge = 0;
    out.elements.resize(count);
    for (size_t k = 0; k < count; ++k) {
      Element& element = out.elements[k];
      element.material = p.material;
      element.surface = int(surfaces[k]) - 1;  // stored + 1, so that 0 means unknown
      element.corners.assign(corners.begin() + offsets[k], corners.begin() + offsets[k + 1]);
      if (orders[k] == 2.0) {
        element.midEdge.assign(midEdges.begin() + ptrdiff_t(nextMidEdge),
                               midEdges.begin() + ptrdiff_t(nextMidEdge + element.corners.size()));
        nextMidEdge += element.corners.size();
      }
    }
    return out;
  }

  // Places every primitive's vertices and elements at their mesh indices. A node stored by
  // several primitives (it borders elements of several materials) must be stored the same way
  // by each; an element must be stored once.
  void assemble(const std::vector<StoredPrimitive>& primitives, uint64_t nodeCount, uint64_t elementCount) {
    std::vector<char> nodeStored(nodeCount, 0), elementStored(elementCount, 0);
    mesh_.nodes.resize(nodeCount);
    mesh_.elements.resize(elementCount);
    for (const StoredPrimitive& p : primitives) {
      for (size_t v = 0; v < p.vertices.size(); ++v) {
        const uint32_t n = p.node[v];
        const Node& stored = mesh_.nodes[n];
        const Node& node = p.vertices[v];
        if (nodeStored[n] &&
            (stored.position != node.position || stored.B != node.B || stored.gradient != node.gradient ||
             stored.standardError != node.standardError))
          fail(p.what + ": node " + std::to_string(n) + " differs from its copy in an earlier primitive");
        mesh_.nodes[n] = node;
        nodeStored[n] = 1;
      }
      for (size_t k = 0; k < p.elements.size(); ++k) {
        const uint32_t e = p.element[k];
        if (elementStored[e]) fail(p.what + ": element " + std::to_string(e) + " is stored a second time");
        elementStored[e] = 1;
        Element& element = mesh_.elements[e];
        element = p.elements[k];
        for (uint32_t& c : element.corners) c = p.node[c];  // vertex index -> node index
        for (uint32_t& m : element.midEdge) m = p.node[m];
      }
    }
    for (size_t n = 0; n < nodeCount; ++n)
      if (!nodeStored[n]) fail("node " + std::to_string(n) + " is stored in no primitive");
  }

  void readDiscontinuities(const tinygltf::Value& ext) {
    const bool hasNodes = ext.Has("discontinuityNodes"), hasOrders = ext.Has("discontinuityOrders");
    if (hasNodes != hasOrders)
      fail(std::string(kSolutionExtension) + ": discontinuityNodes and discontinuityOrders come together");
    if (!hasNodes) return;
    const std::string what = std::string(kSolutionExtension) + ".discontinuityNodes";
    const std::vector<uint32_t> nodes =
        doc_.readUnsigned(integer(ext, "discontinuityNodes", kSolutionExtension), what, mesh_.nodes.size());
    const std::vector<double> orders =
        doc_.readAccessor(integer(ext, "discontinuityOrders", kSolutionExtension),
                          {std::string(kSolutionExtension) + ".discontinuityOrders", 1, kByte, false});
    checkLimit(doc_.path(), orders.size(), kMaxDiscontinuityEdges, "discontinuity edges");
    if (nodes.size() != 2 * orders.size())
      fail(what + " has " + std::to_string(nodes.size()) + " nodes for " + std::to_string(orders.size()) +
           " edges (expected 2 per edge)");
    for (size_t d = 0; d < orders.size(); ++d) {
      if (orders[d] < -1.0 || orders[d] > 1.0)
        fail(std::string(kSolutionExtension) + ".discontinuityOrders: edge " + std::to_string(d) + " has order " +
             std::to_string(int(orders[d])) + " (expected -1, 0 or 1)");
      mesh_.discontinuities.push_back({nodes[2 * d], nodes[2 * d + 1], Continuity(int8_t(orders[d]))});
    }
  }

  const GltfDocument& doc_;
  const tinygltf::Model& model_;
  RadiosityMesh mesh_;
};

}  // namespace

bool isSolution(const GltfDocument& document) { return document.model().extensions.count(kSolutionExtension) > 0; }

RadiosityMesh readSolution(const GltfDocument& document) { return SolutionReader(document).read(); }

}  // namespace radview
