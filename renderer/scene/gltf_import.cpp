#include "scene/gltf_import.h"

#include "core/error.h"
#include "core/limits.h"

#include <tiny_gltf.h>
#include <glm/gtc/constants.hpp>

#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace radview {

namespace {

using Mat4 = glm::dmat4;

// A triangle whose doubled area is below this fraction of its longest edge squared is taken
// as degenerate: repeated vertices and exactly collinear ones, up to double rounding.
constexpr double kDegenerateRatio = 1e-10;

// Extensions the import reads; every other one in extensionsUsed is reported as ignored.
const char* const kExtensionsRead[] = {"KHR_mesh_quantization", "KHR_materials_emissive_strength"};

const char* modeName(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS:
      return "POINTS";
    case TINYGLTF_MODE_LINE:
      return "LINES";
    case TINYGLTF_MODE_LINE_LOOP:
      return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP:
      return "LINE_STRIP";
    default:
      return "?";
  }
}

bool finite(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

bool degenerate(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double longest2 = std::max({glm::dot(b - a, b - a), glm::dot(c - a, c - a), glm::dot(c - b, c - b)});
  return !(glm::length(glm::cross(b - a, c - a)) > kDegenerateRatio * longest2);
}

class SceneImporter {
 public:
  SceneImporter(const GltfDocument& document, std::vector<std::string>& warnings, const PrimitiveVisitor& visit = {},
                bool colourModulatesRho = true)
      : doc_(document),
        model_(document.model()),
        warnings_(warnings),
        visit_(visit),
        colourModulatesRho_(colourModulatesRho) {}

  // The cameras alone, for a file whose meshes are read another way (a solution file).
  std::vector<SceneCamera> cameras() {
    withMeshes_ = false;
    const std::vector<int> parent = checkNodeTree();
    for (int root : rootNodes(parent)) walk(root);
    warnIf(ignoredCameras_, "orthographic or degenerate camera(s) ignored");
    return std::move(scene_.cameras);
  }

  Scene run() {
    const std::vector<int> parent = checkNodeTree();
    for (int root : rootNodes(parent)) walk(root);
    summarizeWarnings();
    if (scene_.polygons.empty())
      fail("no triangles to show (" + std::to_string(trianglePrimitives_) + " triangle primitive(s) in the scene)");
    return std::move(scene_);
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw Error(doc_.path(), problem); }

  // glTF nodes form a forest (spec, "Nodes and Hierarchy"): every child index in range, at
  // most one parent per node, no cycles. Returns each node's parent (-1 for roots).
  std::vector<int> checkNodeTree() const {
    const int count = int(model_.nodes.size());
    std::vector<int> parent(size_t(count), -1);
    for (int n = 0; n < count; ++n)
      for (int child : model_.nodes[size_t(n)].children) {
        if (child < 0 || child >= count)
          fail("node " + std::to_string(n) + ": child " + std::to_string(child) + " does not exist (the file has " +
               std::to_string(count) + " nodes)");
        if (parent[size_t(child)] != -1)
          fail("node " + std::to_string(child) + " has two parents (nodes " + std::to_string(parent[size_t(child)]) +
               " and " + std::to_string(n) + "); glTF nodes must form a tree");
        parent[size_t(child)] = n;
      }
    // With one parent each, a node lies on a cycle exactly when climbing from it never ends.
    enum State : char { kUnknown, kClimbing, kReachesRoot };
    std::vector<State> state(size_t(count), kUnknown);
    for (int start = 0; start < count; ++start) {
      std::vector<int> path;
      int n = start;
      while (n != -1 && state[size_t(n)] == kUnknown) {
        state[size_t(n)] = kClimbing;
        path.push_back(n);
        n = parent[size_t(n)];
      }
      if (n != -1 && state[size_t(n)] == kClimbing)
        fail("node " + std::to_string(n) + " is its own ancestor (a cycle in the node hierarchy)");
      for (int p : path) state[size_t(p)] = kReachesRoot;
    }
    return parent;
  }

  std::vector<int> rootNodes(const std::vector<int>& parent) const {
    std::vector<int> roots;
    if (model_.defaultScene < 0) {
      for (int n = 0; n < int(parent.size()); ++n)
        if (parent[size_t(n)] == -1) roots.push_back(n);
      return roots;
    }
    if (size_t(model_.defaultScene) >= model_.scenes.size())
      fail("the default scene " + std::to_string(model_.defaultScene) + " does not exist (the file has " +
           std::to_string(model_.scenes.size()) + " scenes)");
    const std::string sceneName = "scene " + std::to_string(model_.defaultScene);
    for (int n : model_.scenes[size_t(model_.defaultScene)].nodes) {
      if (n < 0 || size_t(n) >= parent.size())
        fail(sceneName + ": node " + std::to_string(n) + " does not exist (the file has " +
             std::to_string(parent.size()) + " nodes)");
      if (parent[size_t(n)] != -1)
        fail(sceneName + " lists node " + std::to_string(n) + " as a root, but it is a child of node " +
             std::to_string(parent[size_t(n)]));
      if (std::find(roots.begin(), roots.end(), n) != roots.end())
        fail(sceneName + " lists node " + std::to_string(n) + " twice");
      roots.push_back(n);
    }
    return roots;
  }

  // Depth-first over one root's subtree with an explicit stack: a deep file cannot overflow ours.
  void walk(int root) {
    struct Pending {
      int node;
      Mat4 worldFromParent;
      int depth;
    };
    std::vector<Pending> stack{{root, Mat4(1.0), 0}};
    while (!stack.empty()) {
      const Pending item = stack.back();
      stack.pop_back();
      if (item.depth > kMaxNodeDepth)
        fail("the node hierarchy is deeper than " + std::to_string(kMaxNodeDepth) + " levels at node " +
             std::to_string(item.node));
      const tinygltf::Node& node = model_.nodes[size_t(item.node)];
      const Mat4 worldFromNode = item.worldFromParent * localTransform(node, item.node);
      if (node.mesh >= 0 && withMeshes_) addMesh(node, item.node, worldFromNode);
      if (node.camera >= 0) addCamera(node, item.node, worldFromNode);
      if (node.skin >= 0) ++skinnedNodes_;
      // Reversed, so that children pop in file order and polygons keep the file's order.
      for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
        stack.push_back({*child, worldFromNode, item.depth + 1});
    }
  }

  // Spec, "Transformations": either a column-major matrix or T * R * S.
  Mat4 localTransform(const tinygltf::Node& node, int index) const {
    const std::string name = "node " + std::to_string(index);
    auto checkVector = [&](const std::vector<double>& v, size_t size, const char* property) {
      if (!v.empty() && v.size() != size)
        fail(name + ": " + property + " has " + std::to_string(v.size()) + " values, expected " + std::to_string(size));
      if (!finite(v)) fail(name + ": " + property + " is not finite");
    };
    if (!node.matrix.empty()) {
      checkVector(node.matrix, 16, "matrix");
      const Mat4 m = glm::make_mat4(node.matrix.data());
      if (glm::row(m, 3) != glm::dvec4(0.0, 0.0, 0.0, 1.0))
        fail(name + ": matrix is not affine (its last row is not 0 0 0 1)");
      return m;
    }
    checkVector(node.translation, 3, "translation");
    checkVector(node.rotation, 4, "rotation");
    checkVector(node.scale, 3, "scale");
    Mat4 m(1.0);
    if (!node.translation.empty()) m = glm::translate(m, glm::make_vec3(node.translation.data()));
    if (!node.rotation.empty()) {
      // glTF stores x, y, z, w; glm's constructor takes w first.
      glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
      const double length = glm::length(q);
      if (!(length > 0.0) || !std::isfinite(length)) fail(name + ": rotation is not a usable quaternion");
      m *= glm::mat4_cast(q / length);
    }
    if (!node.scale.empty()) m = glm::scale(m, glm::make_vec3(node.scale.data()));
    return m;
  }

  void addMesh(const tinygltf::Node& node, int nodeIndex, const Mat4& worldFromMesh) {
    if (size_t(node.mesh) >= model_.meshes.size())
      fail("node " + std::to_string(nodeIndex) + ": mesh " + std::to_string(node.mesh) +
           " does not exist (the file has " + std::to_string(model_.meshes.size()) + " meshes)");
    const tinygltf::Mesh& mesh = model_.meshes[size_t(node.mesh)];
    for (size_t p = 0; p < mesh.primitives.size(); ++p)
      addPrimitive(mesh.primitives[p], "mesh " + std::to_string(node.mesh) + " primitive " + std::to_string(p),
                   nodeIndex, worldFromMesh);
  }

  void addPrimitive(const tinygltf::Primitive& primitive, const std::string& what, int nodeIndex,
                    const Mat4& worldFromMesh) {
    const int mode = primitive.mode;
    if (mode >= TINYGLTF_MODE_POINTS && mode <= TINYGLTF_MODE_LINE_STRIP) {
      ++skippedByMode_[mode];
      return;
    }
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN)
      fail(what + ": mode " + std::to_string(mode) + " is not a glTF primitive mode");
    ++trianglePrimitives_;
    if (!primitive.targets.empty()) ++morphedPrimitives_;
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) {
      ++withoutPosition_;
      return;
    }

    // KHR_mesh_quantization lets positions be (normalized) integers.
    const bool quantized = doc_.usesExtension("KHR_mesh_quantization");
    const unsigned positionTypes = quantized ? kFloat | kByte | kUnsignedByte | kShort | kUnsignedShort : kFloat;
    std::vector<Vec3> positions = doc_.readVec3(position->second, {what + " POSITION", 3, positionTypes, quantized});
    for (Vec3& p : positions) {
      p = Vec3(worldFromMesh * glm::dvec4(p, 1.0));
      if (!isFinite(p)) fail(what + " on node " + std::to_string(nodeIndex) + ": a transformed position is not finite");
    }
    std::vector<uint32_t> indices;
    if (primitive.indices >= 0) {
      indices =
          doc_.readUnsigned(primitive.indices, what + " indices", positions.size(), GltfDocument::Restart::Forbidden);
    } else {
      indices.resize(positions.size());
      for (uint32_t i = 0; i < indices.size(); ++i) indices[i] = i;
    }
    // A mirroring transform turns counter-clockwise triangles clockwise; swapping two
    // vertices turns them back, so polygon normals still point out of the front face.
    const bool mirrored = glm::determinant(glm::dmat3(worldFromMesh)) < 0.0;
    const int material = sceneMaterial(primitive.material, what);
    const std::vector<Rgb> colours =
        colourModulatesRho_ ? readVertexColours(doc_, primitive, what, positions.size()) : std::vector<Rgb>{};
    std::vector<std::array<uint32_t, 3>> triangles;  // for visit_ only
    auto emit = [&](uint32_t a, uint32_t b, uint32_t c) {
      if (mirrored) std::swap(b, c);
      const Vec3 &pa = positions[a], &pb = positions[b], &pc = positions[c];
      if (degenerate(pa, pb, pc)) {
        ++degenerateTriangles_;
        return;
      }
      if (scene_.polygons.size() >= kMaxSceneTriangles)
        fail("more than " + std::to_string(kMaxSceneTriangles) +
             " triangles after instancing; radview does not mesh scenes that large");
      const int triangleMaterial =
          colours.empty() ? material : modulatedMaterial(material, (colours[a] + colours[b] + colours[c]) / 3.0);
      scene_.polygons.push_back({{pa, pb, pc}, triangleMaterial});
      if (visit_) triangles.push_back({a, b, c});
    };
    // The spec ("Meshes") gives the vertex order of each triangle of a strip and a fan.
    const size_t n = indices.size();
    if (n < 3) {
      ++tooFewVertices_;
    } else if (mode == TINYGLTF_MODE_TRIANGLES) {
      if (n % 3 != 0) ++ragged_;
      for (size_t i = 0; i + 2 < n; i += 3) emit(indices[i], indices[i + 1], indices[i + 2]);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      for (size_t i = 0; i + 2 < n; ++i) emit(indices[i], indices[i + 1 + i % 2], indices[i + 2 - i % 2]);
    } else {
      for (size_t i = 0; i + 2 < n; ++i) emit(indices[i + 1], indices[i + 2], indices[0]);
    }
    if (visit_) visit_({primitive, what, positions, triangles, material});
  }

  // The scene material of glTF material `index` (-1: the spec's default material), converted
  // on first use so that materials nothing uses are never judged.
  int sceneMaterial(int index, const std::string& what) {
    const auto known = materialOf_.find(index);
    if (known != materialOf_.end()) return known->second;
    Material material;
    if (index < 0) {
      material = {"glTF default material", Rgb(1.0), Rgb(0.0)};
    } else if (size_t(index) >= model_.materials.size()) {
      fail(what + ": material " + std::to_string(index) + " does not exist (the file has " +
           std::to_string(model_.materials.size()) + " materials)");
    } else {
      material = convertMaterial(index);
    }
    scene_.materials.push_back(material);
    return materialOf_[index] = int(scene_.materials.size()) - 1;
  }

  // Scene material `material` with its rho times `colour`, made once per material and 8-bit
  // colour (finer steps than that would multiply materials without a visible difference).
  int modulatedMaterial(int material, const Rgb& colour) {
    const glm::ivec3 step = glm::ivec3(glm::round(glm::clamp(colour, 0.0, 1.0) * 255.0));
    const auto key = std::make_tuple(material, step.r, step.g, step.b);
    const auto known = modulated_.find(key);
    if (known != modulated_.end()) return known->second;
    Material m = scene_.materials[size_t(material)];
    m.rho *= Rgb(step) / 255.0;
    m.name += " x COLOR_0";
    scene_.materials.push_back(m);
    ++colouredTriangleMaterials_;
    return modulated_[key] = int(scene_.materials.size()) - 1;
  }

  Material convertMaterial(int index) {
    const tinygltf::Material& m = model_.materials[size_t(index)];
    const std::string name = "material " + std::to_string(index);
    const std::vector<double>& base = m.pbrMetallicRoughness.baseColorFactor;
    const std::vector<double>& emissive = m.emissiveFactor;
    if (base.size() != 4 || !finite(base)) fail(name + ": baseColorFactor is not 4 finite numbers");
    if (emissive.size() != 3 || !finite(emissive)) fail(name + ": emissiveFactor is not 3 finite numbers");
    const Rgb rawRho(base[0], base[1], base[2]);
    const Rgb rawEmissive(emissive[0], emissive[1], emissive[2]);
    const Rgb rho = glm::clamp(rawRho, 0.0, 1.0);
    const Rgb emissiveFactor = glm::clamp(rawEmissive, 0.0, 1.0);
    if (rho != rawRho || emissiveFactor != rawEmissive) ++clampedMaterials_;

    double strength = 1.0;
    const auto ext = m.extensions.find("KHR_materials_emissive_strength");
    if (ext != m.extensions.end() && ext->second.Has("emissiveStrength")) {
      const tinygltf::Value& value = ext->second.Get("emissiveStrength");
      if (!value.IsNumber() || !std::isfinite(value.GetNumberAsDouble()) || value.GetNumberAsDouble() < 0.0)
        fail(name + ": KHR_materials_emissive_strength.emissiveStrength is not a finite number >= 0");
      strength = value.GetNumberAsDouble();
    }
    return {m.name.empty() ? name : m.name, rho, emissiveFactor * strength};
  }

  void addCamera(const tinygltf::Node& node, int nodeIndex, const Mat4& worldFromCamera) {
    if (size_t(node.camera) >= model_.cameras.size())
      fail("node " + std::to_string(nodeIndex) + ": camera " + std::to_string(node.camera) +
           " does not exist (the file has " + std::to_string(model_.cameras.size()) + " cameras)");
    const tinygltf::Camera& camera = model_.cameras[size_t(node.camera)];
    if (camera.type != "perspective") {
      ++ignoredCameras_;
      return;
    }
    const double yfov = camera.perspective.yfov;
    if (!(yfov > 0.0 && yfov < glm::pi<double>()))
      fail("camera " + std::to_string(node.camera) + ": yfov " + std::to_string(yfov) + " is not in (0, pi)");
    // Spec, "Cameras": the camera looks down its node's -Z with +Y up.
    const glm::dmat3 linear(worldFromCamera);
    const Vec3 eye(worldFromCamera[3]);
    const Vec3 forward = glm::normalize(linear * Vec3(0.0, 0.0, -1.0));
    Vec3 up = linear * Vec3(0.0, 1.0, 0.0);
    up = glm::normalize(up - glm::dot(up, forward) * forward);  // a sheared node still gets a square camera
    if (!std::isfinite(forward.x + forward.y + forward.z + up.x + up.y + up.z)) {
      ++ignoredCameras_;
      return;
    }
    std::string name = camera.name.empty() ? node.name : camera.name;
    if (name.empty()) name = "camera " + std::to_string(node.camera);
    scene_.cameras.push_back({name, eye, eye + forward, up, yfov});
  }

  void warnIf(size_t count, const std::string& message) {
    if (count > 0) warnings_.push_back(std::to_string(count) + " " + message);
  }

  void summarizeWarnings() {
    for (const auto& [mode, count] : skippedByMode_)
      warnIf(count, std::string(modeName(mode)) + " primitive(s) skipped: radview shows triangles only");
    warnIf(withoutPosition_, "triangle primitive(s) without POSITION skipped");
    warnIf(tooFewVertices_, "triangle primitive(s) with fewer than 3 vertices skipped");
    warnIf(ragged_, "TRIANGLES primitive(s) with a vertex count not a multiple of 3: the extra vertices ignored");
    warnIf(degenerateTriangles_, "degenerate (zero-area) triangle(s) dropped");
    warnIf(colouredTriangleMaterials_,
           "material(s) made for COLOR_0: each triangle's rho is its material's times its corners' mean COLOR_0");
    warnIf(clampedMaterials_, "material(s) with a colour factor outside [0,1], clamped");
    warnIf(ignoredCameras_, "orthographic or degenerate camera(s) ignored");
    warnIf(model_.animations.size(), "animation(s) ignored: radview shows the rest pose");
    warnIf(skinnedNodes_, "skinned node(s) shown unskinned");
    warnIf(morphedPrimitives_, "primitive(s) with morph targets shown without them");
    for (const std::string& name : model_.extensionsUsed)
      if (std::none_of(std::begin(kExtensionsRead), std::end(kExtensionsRead),
                       [&](const char* r) { return name == r; }))
        warnings_.push_back("extension " + name + " ignored");
  }

  const GltfDocument& doc_;
  const tinygltf::Model& model_;
  std::vector<std::string>& warnings_;
  PrimitiveVisitor visit_;
  bool colourModulatesRho_ = true;
  std::map<std::tuple<int, int, int, int>, int> modulated_;  // (material, 8-bit colour) -> scene material
  size_t colouredTriangleMaterials_ = 0;
  bool withMeshes_ = true;
  Scene scene_;
  std::map<int, int> materialOf_;  // glTF material index (-1: default) -> scene material
  std::map<int, size_t> skippedByMode_;
  size_t trianglePrimitives_ = 0, withoutPosition_ = 0, tooFewVertices_ = 0, ragged_ = 0;
  size_t degenerateTriangles_ = 0, clampedMaterials_ = 0, ignoredCameras_ = 0;
  size_t skinnedNodes_ = 0, morphedPrimitives_ = 0;
};

}  // namespace

std::vector<Rgb> readVertexColours(const GltfDocument& document, const tinygltf::Primitive& primitive,
                                   const std::string& what, size_t vertexCount, bool* integer) {
  const auto colour = primitive.attributes.find("COLOR_0");
  if (colour == primitive.attributes.end()) return {};
  const tinygltf::Model& model = document.model();
  const int accessor = colour->second;
  const bool vec4 = accessor >= 0 && size_t(accessor) < model.accessors.size() &&
                    model.accessors[size_t(accessor)].type == TINYGLTF_TYPE_VEC4;
  const size_t components = vec4 ? 4 : 3;
  const std::vector<double> values = document.readAccessor(
      accessor, {what + " COLOR_0", int(components), kFloat | kUnsignedByte | kUnsignedShort, true});
  const tinygltf::Accessor& stored = model.accessors[size_t(accessor)];
  const bool isInteger = stored.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT;
  if (isInteger && !stored.normalized)
    throw Error(document.path(), what + " COLOR_0: integer colours must be normalized (glTF 2.0, \"Meshes\")");
  if (integer) *integer = isInteger;
  if (values.size() != vertexCount * components)
    throw Error(document.path(), what + " COLOR_0: " + std::to_string(values.size() / components) + " colours for " +
                                     std::to_string(vertexCount) + " vertices");
  std::vector<Rgb> colours(vertexCount);
  for (size_t v = 0; v < vertexCount; ++v)
    colours[v] = Rgb(values[v * components], values[v * components + 1], values[v * components + 2]);
  return colours;
}

Scene importScene(const GltfDocument& document, std::vector<std::string>& warnings, const PrimitiveVisitor& visit,
                  bool colourModulatesRho) {
  return SceneImporter(document, warnings, visit, colourModulatesRho).run();
}

std::vector<SceneCamera> importCameras(const GltfDocument& document, std::vector<std::string>& warnings) {
  return SceneImporter(document, warnings).cameras();
}

}  // namespace radview
