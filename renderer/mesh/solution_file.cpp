#include "mesh/solution_file.h"

#include "core/atomic_file.h"
#include "core/display_transform.h"
#include "core/error.h"
#include "core/limits.h"
#include "core/strings.h"
#include "geom/polygon.h"

#include <glm/gtc/constants.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <sstream>

namespace radview {

namespace {

constexpr int kFormatVersion = 1;
constexpr int kArrayBuffer = 34962;         // bufferView.target of vertex attributes
constexpr int kElementArrayBuffer = 34963;  // bufferView.target of indices
constexpr uint32_t kNoVertex = UINT32_MAX;

const char* const kGradientAttributes[3] = {"_RADIOSITY_GRADIENT_R", "_RADIOSITY_GRADIENT_G",
                                            "_RADIOSITY_GRADIENT_B"};



tinygltf::Value numbers(const Rgb& v) {
  return tinygltf::Value(
      tinygltf::Value::Array{tinygltf::Value(v.r), tinygltf::Value(v.g), tinygltf::Value(v.b)});
}

// --- writing ----------------------------------------------------------------------------

// Appends accessor data to the model's only buffer, one 4-byte-aligned bufferView each.
class BufferWriter {
 public:
  explicit BufferWriter(tinygltf::Model& model) : model_(model) { model_.buffers.emplace_back(); }

  int vec3s(const std::vector<glm::vec3>& values, bool withBounds) {
    const int index = add(values.data(), values.size() * sizeof(glm::vec3), TINYGLTF_COMPONENT_TYPE_FLOAT,
                          TINYGLTF_TYPE_VEC3, values.size(), kArrayBuffer);
    if (withBounds) {  // glTF requires min and max on POSITION
      glm::vec3 lo = values[0], hi = values[0];
      for (const glm::vec3& v : values) lo = glm::min(lo, v), hi = glm::max(hi, v);
      model_.accessors.back().minValues = {lo.x, lo.y, lo.z};
      model_.accessors.back().maxValues = {hi.x, hi.y, hi.z};
    }
    return index;
  }
  int uints(const std::vector<uint32_t>& values, int target = 0) {
    return add(values.data(), values.size() * 4, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
               values.size(), target);
  }
  int ubytes(const std::vector<uint8_t>& values) {
    return add(values.data(), values.size(), TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_SCALAR,
               values.size(), 0);
  }
  int bytes(const std::vector<int8_t>& values) {
    return add(values.data(), values.size(), TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_TYPE_SCALAR,
               values.size(), 0);
  }

 private:
  int add(const void* data, size_t size, int componentType, int type, size_t count, int target) {
    std::vector<unsigned char>& buffer = model_.buffers[0].data;
    buffer.resize((buffer.size() + 3) / 4 * 4);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = size;
    view.target = target;
    const unsigned char* bytes = static_cast<const unsigned char*>(data);
    buffer.insert(buffer.end(), bytes, bytes + size);
    model_.bufferViews.push_back(view);
    tinygltf::Accessor accessor;
    accessor.bufferView = int(model_.bufferViews.size()) - 1;
    accessor.componentType = componentType;
    accessor.type = type;
    accessor.count = count;
    model_.accessors.push_back(accessor);
    return int(model_.accessors.size()) - 1;
  }

  tinygltf::Model& model_;
};

// Triangles, as global node triples, that show element `e` in other viewers: its corner
// polygon, or for a quadratic element the polygon through corners and mid-edge nodes, so
// that the mid-edge values appear. A convex quadratic element is cut into its corner
// triangles (m_{i-1}, c_i, m_i) and the polygon of mid-edge nodes; a fan from a corner would
// give zero-area triangles along the straight edges.
std::vector<std::array<uint32_t, 3>> displayTriangles(const RadiosityMesh& mesh, size_t element) {
  const Element& e = mesh.elements[element];
  std::vector<std::array<uint32_t, 3>> out;
  const size_t n = e.corners.size();
  auto addTriangulated = [&](const std::vector<uint32_t>& ring) {
    std::vector<Vec3> positions;
    for (uint32_t node : ring) positions.push_back(mesh.nodes[node].position);
    for (const std::array<int, 3>& t : triangulatePolygon(positions))
      out.push_back({ring[size_t(t[0])], ring[size_t(t[1])], ring[size_t(t[2])]});
  };
  try {
    if (e.midEdge.empty()) {
      addTriangulated(e.corners);
    } else if (isConvex(mesh.cornerPositions(element))) {
      for (size_t i = 0; i < n; ++i) {
        const std::array<uint32_t, 3> cut{e.midEdge[(i + n - 1) % n], e.corners[i], e.midEdge[i]};
        // At a straight corner (a T-vertex turned corner) the cut is flat: nothing to show.
        const std::vector<Vec3> cutPositions{mesh.nodes[cut[0]].position, mesh.nodes[cut[1]].position,
                                             mesh.nodes[cut[2]].position};
        if (unitNormal(cutPositions) != Vec3(0.0)) out.push_back(cut);
      }
      addTriangulated(e.midEdge);
    } else {
      std::vector<uint32_t> ring;
      for (size_t i = 0; i < n; ++i) ring.insert(ring.end(), {e.corners[i], e.midEdge[i]});
      addTriangulated(ring);
    }
  } catch (const Error&) {
    // A degenerate element (zero area) cannot be triangulated; it has nothing to show, and the
    // extension still records it, so a fan over its corners is as good as anything.
    out.clear();
    for (size_t i = 1; i + 1 < n; ++i) out.push_back({e.corners[0], e.corners[i], e.corners[i + 1]});
  }
  return out;
}

class SolutionWriter {
 public:
  SolutionWriter(const RadiosityMesh& mesh, const std::vector<SceneCamera>& cameras, const std::string& path)
      : mesh_(mesh), cameras_(cameras), path_(path), buffer_(model_), localOf_(mesh.nodes.size(), kNoVertex) {}

  tinygltf::Model build() {
    const double scale = toneMapScale(mesh_);
    std::vector<std::vector<uint32_t>> elementsOf(mesh_.materials.size());
    for (uint32_t e = 0; e < mesh_.elements.size(); ++e)
      elementsOf[size_t(mesh_.elements[e].material)].push_back(e);
    tinygltf::Mesh gltfMesh;
    gltfMesh.name = "radiosity solution";
    bool first = true;
    for (size_t m = 0; m < elementsOf.size(); ++m) {
      if (elementsOf[m].empty()) continue;
      gltfMesh.primitives.push_back(primitive(int(m), elementsOf[m], scale, first));
      first = false;
    }
    model_.meshes.push_back(gltfMesh);
    for (const Material& material : mesh_.materials) model_.materials.push_back(gltfMaterial(material));

    tinygltf::Node node;
    node.mesh = 0;
    model_.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes = {0};
    for (size_t c = 0; c < cameras_.size(); ++c) {
      scene.nodes.push_back(int(model_.nodes.size()));
      addCamera(cameras_[c], c);
    }
    model_.scenes.push_back(scene);
    model_.defaultScene = 0;
    model_.asset.version = "2.0";
    model_.asset.generator = "radview";
    model_.extensionsUsed = {"KHR_materials_unlit", kSolutionExtension};
    model_.extensions[kSolutionExtension] = rootExtension(scale);
    return std::move(model_);
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw Error(path_, problem); }

  // A standard glTF perspective camera on its own node (spec, "Cameras": it looks down the
  // node's -Z with +Y up), so that any glTF viewer opens the solution where the scene's
  // author looked from, and radview finds it the way it finds a scene's (importCameras).
  void addCamera(const SceneCamera& camera, size_t index) {
    const Vec3 forward = glm::normalize(camera.target - camera.eye);
    const Vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const Vec3 up = glm::cross(right, forward);
    const std::string what = "camera " + std::to_string(index) + " (" + camera.name + ")";
    if (!std::isfinite(glm::dot(right, right) + glm::dot(camera.eye, camera.eye)))
      fail(what + ": its eye, target and up do not make a view (not finite, or up along the view)");
    if (!(camera.yfov > 0.0 && camera.yfov < glm::pi<double>()))
      fail(what + ": yfov " + std::to_string(camera.yfov) + " is not in (0, pi)");
    tinygltf::Camera gltfCamera;
    gltfCamera.name = camera.name;
    gltfCamera.type = "perspective";
    gltfCamera.perspective.yfov = camera.yfov;
    // glTF requires clip planes (tinygltf would write an invalid zfar of 0 for "infinite").
    // radview fits its own to the scene; other viewers get a near plane a thousandth of the
    // mesh's diagonal and a far one well past its farthest point.
    const Bounds bounds = mesh_.bounds();
    const double diagonal = bounds.diagonal();
    gltfCamera.perspective.znear = diagonal > 0.0 ? 1e-3 * diagonal : 1e-3;
    gltfCamera.perspective.zfar = std::max(2.0 * (glm::distance(camera.eye, bounds.center()) + diagonal),
                                           2.0 * gltfCamera.perspective.znear);
    model_.cameras.push_back(gltfCamera);

    tinygltf::Node node;
    node.name = camera.name;
    node.camera = int(model_.cameras.size()) - 1;
    node.matrix = {right.x,    right.y,    right.z,    0.0,  // column-major: the node's +X,
                   up.x,       up.y,       up.z,       0.0,  // +Y,
                   -forward.x, -forward.y, -forward.z, 0.0,  // +Z
                   camera.eye.x, camera.eye.y, camera.eye.z, 1.0};  // and origin
    model_.nodes.push_back(node);
  }

  glm::vec3 toFloat(const Vec3& v, size_t node, const char* what) const {
    const glm::vec3 f(v);
    if (!std::isfinite(f.x) || !std::isfinite(f.y) || !std::isfinite(f.z))
      fail("node " + std::to_string(node) + ": " + what + " does not fit in float32");
    return f;
  }

  // The nodes stored in a primitive: those its elements use, in global order; the first
  // primitive also takes the nodes no element uses, so that every node is stored somewhere.
  std::vector<uint32_t> primitiveNodes(const std::vector<uint32_t>& elements, bool takeOrphans) const {
    std::vector<char> used(mesh_.nodes.size(), 0);
    for (uint32_t e : elements) {
      for (uint32_t n : mesh_.elements[e].corners) used[n] = 1;
      for (uint32_t n : mesh_.elements[e].midEdge) used[n] = 1;
    }
    if (takeOrphans) {
      std::vector<char> usedAnywhere(mesh_.nodes.size(), 0);
      for (const Element& element : mesh_.elements) {
        for (uint32_t n : element.corners) usedAnywhere[n] = 1;
        for (uint32_t n : element.midEdge) usedAnywhere[n] = 1;
      }
      for (size_t n = 0; n < used.size(); ++n) used[n] |= !usedAnywhere[n];
    }
    std::vector<uint32_t> nodes;
    for (uint32_t n = 0; n < used.size(); ++n)
      if (used[n]) nodes.push_back(n);
    return nodes;
  }

  tinygltf::Primitive primitive(int material, const std::vector<uint32_t>& elements, double scale,
                                bool takeOrphans) {
    const std::vector<uint32_t> nodes = primitiveNodes(elements, takeOrphans);
    for (uint32_t v = 0; v < nodes.size(); ++v) localOf_[nodes[v]] = v;

    // NORMAL: the mean of the normals of the primitive's elements around each node.
    std::vector<Vec3> normalSum(nodes.size(), Vec3(0.0)), anyNormal(nodes.size(), Vec3(0.0, 0.0, 1.0));
    std::vector<uint32_t> indices, cornerOffsets{0}, corners, midEdges, surfaces;
    std::vector<uint8_t> orders;
    for (uint32_t e : elements) {
      const Element& element = mesh_.elements[e];
      const Vec3 normal = mesh_.elementNormal(e);
      for (const std::vector<uint32_t>* list : {&element.corners, &element.midEdge})
        for (uint32_t n : *list) {
          normalSum[localOf_[n]] += normal;
          if (normal != Vec3(0.0)) anyNormal[localOf_[n]] = normal;
        }
      for (const auto& t : displayTriangles(mesh_, e))
        indices.insert(indices.end(), {localOf_[t[0]], localOf_[t[1]], localOf_[t[2]]});
      for (uint32_t n : element.corners) corners.push_back(localOf_[n]);
      for (uint32_t n : element.midEdge) midEdges.push_back(localOf_[n]);
      cornerOffsets.push_back(uint32_t(corners.size()));
      orders.push_back(uint8_t(element.order()));
      if (element.surface < -1)
        fail("element " + std::to_string(e) + " has surface id " + std::to_string(element.surface));
      surfaces.push_back(uint32_t(element.surface + 1));  // 0: unknown
    }

    std::vector<glm::vec3> positions, normals, colors, radiosity;
    std::array<std::vector<glm::vec3>, 3> gradients;
    for (uint32_t v = 0; v < nodes.size(); ++v) {
      const Node& node = mesh_.nodes[nodes[v]];
      positions.push_back(toFloat(node.position, nodes[v], "the position"));
      radiosity.push_back(toFloat(node.B, nodes[v], "radiosity"));
      colors.push_back(glm::vec3(glm::clamp(node.B * scale, 0.0, 1.0)));
      const double length = glm::length(normalSum[v]);
      normals.push_back(glm::vec3(length > 1e-12 ? normalSum[v] / length : anyNormal[v]));
      if (mesh_.hasGradients)
        for (int c = 0; c < 3; ++c)
          gradients[size_t(c)].push_back(toFloat(node.gradient[size_t(c)], nodes[v], "a gradient"));
    }

    tinygltf::Primitive p;
    p.mode = TINYGLTF_MODE_TRIANGLES;
    p.material = material;
    p.indices = buffer_.uints(indices, kElementArrayBuffer);
    p.attributes["POSITION"] = buffer_.vec3s(positions, true);
    p.attributes["NORMAL"] = buffer_.vec3s(normals, false);
    p.attributes["COLOR_0"] = buffer_.vec3s(colors, false);
    p.attributes["_RADIOSITY"] = buffer_.vec3s(radiosity, false);
    if (mesh_.hasGradients)
      for (int c = 0; c < 3; ++c)
        p.attributes[kGradientAttributes[c]] = buffer_.vec3s(gradients[size_t(c)], false);

    tinygltf::Value::Object ext;
    ext["node"] = tinygltf::Value(buffer_.uints(nodes));
    ext["element"] = tinygltf::Value(buffer_.uints(elements));
    ext["cornerOffsets"] = tinygltf::Value(buffer_.uints(cornerOffsets));
    ext["corners"] = tinygltf::Value(buffer_.uints(corners));
    ext["order"] = tinygltf::Value(buffer_.ubytes(orders));
    if (!midEdges.empty()) ext["midEdges"] = tinygltf::Value(buffer_.uints(midEdges));
    ext["surface"] = tinygltf::Value(buffer_.uints(surfaces));
    p.extensions[kSolutionExtension] = tinygltf::Value(ext);

    for (uint32_t n : nodes) localOf_[n] = kNoVertex;
    return p;
  }

  // Shown unlit with a white base colour, a viewer displays COLOR_0 as it is: the tone-mapped
  // radiosity. The scene material (rho, E) rides in the extension, exactly.
  static tinygltf::Material gltfMaterial(const Material& material) {
    tinygltf::Material m;
    m.name = material.name;
    m.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
    m.pbrMetallicRoughness.metallicFactor = 0.0;
    m.extensions["KHR_materials_unlit"] = tinygltf::Value(tinygltf::Value::Object{});
    m.extensions[kSolutionExtension] =
        tinygltf::Value(tinygltf::Value::Object{{"rho", numbers(material.rho)}, {"E", numbers(material.E)}});
    return m;
  }

  tinygltf::Value rootExtension(double scale) {
    tinygltf::Value::Object ext;
    ext["version"] = tinygltf::Value(kFormatVersion);
    ext["nodeCount"] = tinygltf::Value(int(mesh_.nodes.size()));
    ext["elementCount"] = tinygltf::Value(int(mesh_.elements.size()));
    ext["hasGradients"] = tinygltf::Value(mesh_.hasGradients);
    ext["toneMapScale"] = tinygltf::Value(scale);
    if (!mesh_.discontinuities.empty()) {
      std::vector<uint32_t> nodePairs;
      std::vector<int8_t> orders;
      for (const DiscontinuityEdge& d : mesh_.discontinuities) {
        nodePairs.insert(nodePairs.end(), {d.a, d.b});
        orders.push_back(int8_t(d.order));
      }
      ext["discontinuityNodes"] = tinygltf::Value(buffer_.uints(nodePairs));
      ext["discontinuityOrders"] = tinygltf::Value(buffer_.bytes(orders));
    }
    return tinygltf::Value(ext);
  }

  const RadiosityMesh& mesh_;
  const std::vector<SceneCamera>& cameras_;
  const std::string& path_;
  tinygltf::Model model_;
  BufferWriter buffer_;
  std::vector<uint32_t> localOf_;  // global node -> vertex of the primitive being built
};

// --- reading ----------------------------------------------------------------------------

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
    if (version != kFormatVersion)
      fail(std::string(kSolutionExtension) + " version " + std::to_string(version) +
           " is not supported (this radview reads version " + std::to_string(kFormatVersion) + ")");
    const uint64_t nodeCount = uint64_t(integer(ext, "nodeCount", kSolutionExtension));
    const uint64_t elementCount = uint64_t(integer(ext, "elementCount", kSolutionExtension));
    checkLimit(doc_.path(), nodeCount, kMaxSolutionNodes, "nodes (" + std::string(kSolutionExtension) + ".nodeCount)");
    checkLimit(doc_.path(), elementCount, kMaxSolutionElements,
               "elements (" + std::string(kSolutionExtension) + ".elementCount)");
    if (!ext.Has("hasGradients") || !ext.Get("hasGradients").IsBool())
      fail(std::string(kSolutionExtension) + ": hasGradients is not a boolean");
    mesh_.hasGradients = ext.Get("hasGradients").Get<bool>();
    for (size_t m = 0; m < model_.materials.size(); ++m) mesh_.materials.push_back(material(m));

    // Everything is read (and so bounded by the file's bytes) before nodeCount and
    // elementCount, mere JSON numbers, decide an allocation.
    std::vector<StoredPrimitive> primitives;
    uint64_t vertices = 0, elements = 0;
    for (size_t m = 0; m < model_.meshes.size(); ++m)
      for (size_t p = 0; p < model_.meshes[m].primitives.size(); ++p) {
        primitives.push_back(readPrimitive(model_.meshes[m].primitives[p],
                                           "mesh " + std::to_string(m) + " primitive " + std::to_string(p),
                                           nodeCount, elementCount));
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
      if (!x.IsNumber() || !std::isfinite(x.GetNumberAsDouble()))
        fail(where + ": " + key + " is not 3 finite numbers");
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
    out.vertices.resize(vertexCount);
    for (size_t v = 0; v < vertexCount; ++v) {
      out.vertices[v].position = positions[v];
      out.vertices[v].B = B[v];
      if (mesh_.hasGradients)
        for (size_t c = 0; c < 3; ++c) out.vertices[v].gradient[c] = gradients[c][v];
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
      fail(extWhat + ".cornerOffsets must start at 0 and end at the corner count " +
           std::to_string(corners.size()));
    const std::vector<double> orders =
        doc_.readAccessor(integer(ext, "order", extWhat), {extWhat + ".order", 1, kUnsignedByte, false});
    checkCount("order", orders.size(), count);
    const std::vector<uint32_t> surfaces = readList("surface", uint64_t(INT_MAX) + 1);
    checkCount("surface", surfaces.size(), count);

    size_t midEdgeCount = 0;
    for (size_t k = 0; k < count; ++k) {
      if (offsets[k + 1] < offsets[k] + 3)
        fail(extWhat + ".cornerOffsets: element " + std::to_string(k) + " spans offsets " +
             std::to_string(offsets[k]) + " -> " + std::to_string(offsets[k + 1]) +
             "; they must increase by at least 3 per element");
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
            (stored.position != node.position || stored.B != node.B || stored.gradient != node.gradient))
          fail(p.what + ": node " + std::to_string(n) + " differs from its copy in an earlier primitive");
        mesh_.nodes[n] = node;
        nodeStored[n] = 1;
      }
      for (size_t k = 0; k < p.elements.size(); ++k) {
        const uint32_t e = p.element[k];
        if (elementStored[e])
          fail(p.what + ": element " + std::to_string(e) + " is stored a second time");
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
        fail(std::string(kSolutionExtension) + ".discontinuityOrders: edge " + std::to_string(d) +
             " has order " + std::to_string(int(orders[d])) + " (expected -1, 0 or 1)");
      mesh_.discontinuities.push_back({nodes[2 * d], nodes[2 * d + 1], Continuity(int8_t(orders[d]))});
    }
  }

  const GltfDocument& doc_;
  const tinygltf::Model& model_;
  RadiosityMesh mesh_;
};

}  // namespace

double toneMapScale(const RadiosityMesh& mesh) {
  std::vector<char> lit(mesh.nodes.size(), 0);  // on an element that does not emit
  for (const Element& e : mesh.elements)
    if (!mesh.materials[size_t(e.material)].isEmitter()) {
      for (uint32_t n : e.corners) lit[n] = 1;
      for (uint32_t n : e.midEdge) lit[n] = 1;
    }
  const bool anyLit = std::find(lit.begin(), lit.end(), 1) != lit.end();
  std::vector<double> Y;
  double maxY = 0.0;
  for (size_t n = 0; n < mesh.nodes.size(); ++n) {
    maxY = std::max(maxY, luminance(mesh.nodes[n].B));
    if (lit[n] || !anyLit) Y.push_back(luminance(mesh.nodes[n].B));
  }
  if (Y.empty()) return 1.0;
  auto p99 = Y.begin() + ptrdiff_t(0.99 * double(Y.size() - 1));
  std::nth_element(Y.begin(), p99, Y.end());
  if (*p99 > 0.0) return 0.8 / *p99;
  return maxY > 0.0 ? 0.8 / maxY : 1.0;
}

void writeSolution(const RadiosityMesh& mesh, const std::string& path, const std::vector<SceneCamera>& cameras) {
  const std::string ext = lowerExtension(path);
  if (ext != ".glb" && ext != ".gltf")
    throw Error(path, "unknown solution file type \"" + ext + "\" (radview writes .glb and .gltf)");
  validateMesh(mesh, path);
  if (mesh.elements.empty()) throw Error(path, "the mesh has no element to write");
  // Never a file that radview would refuse to read.
  checkLimit(path, mesh.nodes.size(), kMaxSolutionNodes, "nodes");
  checkLimit(path, mesh.elements.size(), kMaxSolutionElements, "elements");
  checkLimit(path, mesh.discontinuities.size(), kMaxDiscontinuityEdges, "discontinuity edges");
  for (size_t e = 0; e < mesh.elements.size(); ++e)
    checkLimit(path, mesh.elements[e].corners.size(), kMaxElementCorners,
               "corners in element " + std::to_string(e));
  const tinygltf::Model model = SolutionWriter(mesh, cameras, path).build();

  // Serialized in memory rather than by WriteGltfSceneToFile, which ignores failed writes and
  // truncates the old file before it knows the new one can be written.
  std::ostringstream bytes;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, bytes, /*prettyPrint=*/true, /*writeBinary=*/ext == ".glb"))
    throw Error(path, "tinygltf could not serialize the solution");
  writeFileAtomically(path, bytes.str());
}

bool isSolution(const GltfDocument& document) {
  return document.model().extensions.count(kSolutionExtension) > 0;
}

RadiosityMesh readSolution(const GltfDocument& document) { return SolutionReader(document).read(); }

}  // namespace radview
