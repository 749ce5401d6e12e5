// Writing radview's solution files (mesh/solution_file.h): the mesh as glTF primitives whose
// COLOR_0 any viewer shows, and the RADVIEW_radiosity_mesh extension for what glTF cannot say.
#include "mesh/solution_file.h"

#include "core/atomic_file.h"
#include "core/display_transform.h"
#include "core/error.h"
#include "core/limits.h"
#include "core/strings.h"
#include "geom/polygon.h"
#include "mesh/solution_format.h"

#include <tiny_gltf.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace radview {

namespace {

using namespace solution_format;

tinygltf::Value numbers(const Rgb& v) {
  return tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(v.r), tinygltf::Value(v.g), tinygltf::Value(v.b)});
}

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
    return add(values.data(), values.size(), TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_SCALAR, values.size(),
               0);
  }
  int bytes(const std::vector<int8_t>& values) {
    return add(values.data(), values.size(), TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_TYPE_SCALAR, values.size(), 0);
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
    for (uint32_t e = 0; e < mesh_.elements.size(); ++e) elementsOf[size_t(mesh_.elements[e].material)].push_back(e);
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
    gltfCamera.perspective.zfar =
        std::max(2.0 * (glm::distance(camera.eye, bounds.center()) + diagonal), 2.0 * gltfCamera.perspective.znear);
    model_.cameras.push_back(gltfCamera);

    tinygltf::Node node;
    node.name = camera.name;
    node.camera = int(model_.cameras.size()) - 1;
    node.matrix = {right.x,      right.y,      right.z,      0.0,   // column-major: the node's +X,
                   up.x,         up.y,         up.z,         0.0,   // +Y,
                   -forward.x,   -forward.y,   -forward.z,   0.0,   // +Z
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

  tinygltf::Primitive primitive(int material, const std::vector<uint32_t>& elements, double scale, bool takeOrphans) {
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

    std::vector<glm::vec3> positions, normals, colours, radiosity;
    std::array<std::vector<glm::vec3>, 3> gradients;
    std::vector<glm::vec3> standardErrors;
    for (uint32_t v = 0; v < nodes.size(); ++v) {
      const Node& node = mesh_.nodes[nodes[v]];
      positions.push_back(toFloat(node.position, nodes[v], "the position"));
      radiosity.push_back(toFloat(node.B, nodes[v], "radiosity"));
      colours.push_back(glm::vec3(glm::clamp(node.B * scale, 0.0, 1.0)));
      const double length = glm::length(normalSum[v]);
      normals.push_back(glm::vec3(length > 1e-12 ? normalSum[v] / length : anyNormal[v]));
      if (mesh_.hasGradients)
        for (int c = 0; c < 3; ++c)
          gradients[size_t(c)].push_back(toFloat(node.gradient[size_t(c)], nodes[v], "a gradient"));
      if (mesh_.hasStandardErrors)
        standardErrors.push_back(toFloat(node.standardError, nodes[v], "the standard error"));
    }

    tinygltf::Primitive p;
    p.mode = TINYGLTF_MODE_TRIANGLES;
    p.material = material;
    p.indices = buffer_.uints(indices, kElementArrayBuffer);
    p.attributes["POSITION"] = buffer_.vec3s(positions, true);
    p.attributes["NORMAL"] = buffer_.vec3s(normals, false);
    p.attributes["COLOR_0"] = buffer_.vec3s(colours, false);
    p.attributes["_RADIOSITY"] = buffer_.vec3s(radiosity, false);
    if (mesh_.hasGradients)
      for (int c = 0; c < 3; ++c) p.attributes[kGradientAttributes[c]] = buffer_.vec3s(gradients[size_t(c)], false);
    if (mesh_.hasStandardErrors) p.attributes[kStandardErrorAttribute] = buffer_.vec3s(standardErrors, false);

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
    ext["version"] = tinygltf::Value(kVersion);
    ext["nodeCount"] = tinygltf::Value(int(mesh_.nodes.size()));
    ext["elementCount"] = tinygltf::Value(int(mesh_.elements.size()));
    ext["hasGradients"] = tinygltf::Value(mesh_.hasGradients);
    if (mesh_.hasStandardErrors) ext["hasStandardErrors"] = tinygltf::Value(true);
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
    checkLimit(path, mesh.elements[e].corners.size(), kMaxElementCorners, "corners in element " + std::to_string(e));
  const tinygltf::Model model = SolutionWriter(mesh, cameras, path).build();

  // Serialized in memory rather than by WriteGltfSceneToFile, which ignores failed writes and
  // truncates the old file before it knows the new one can be written.
  std::ostringstream bytes;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, bytes, /*prettyPrint=*/true, /*writeBinary=*/ext == ".glb"))
    throw Error(path, "tinygltf could not serialize the solution");
  writeFileAtomically(path, bytes.str());
}

}  // namespace radview
