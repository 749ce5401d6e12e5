#include "import/assimp_mesh.h"

#include "core/error.h"
#include "core/input_file.h"
#include "core/limits.h"
#include "core/strings.h"

#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

namespace radview {

namespace {

// A corner's position and colour, bit for bit: equal keys are one node.
struct CornerKey {
  float values[6];
  bool operator==(const CornerKey& o) const { return std::memcmp(values, o.values, sizeof values) == 0; }
};

struct CornerHash {
  size_t operator()(const CornerKey& k) const {
    uint64_t h = 1469598103934665603ull;
    const auto* bytes = reinterpret_cast<const unsigned char*>(k.values);
    for (size_t i = 0; i < sizeof k.values; ++i) h = (h ^ bytes[i]) * 1099511628211ull;
    return size_t(h);
  }
};

std::string format(const aiVector3D& p) {
  std::ostringstream text;
  text << '(' << p.x << ", " << p.y << ", " << p.z << ')';
  return text.str();
}

std::string format(const aiColor4D& c) {
  std::ostringstream text;
  text << c.r << ' ' << c.g << ' ' << c.b;
  return text.str();
}

// Whether `path` is an OBJ whose every `mtllib` names a file beside it. Only then are its
// materials the file's: for a `usemtl` name it cannot find, Assimp makes a material with
// default colours.
bool materialLibraryFound(const std::string& path) {
  if (lowerExtension(path) != ".obj") return false;
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::ifstream in(path, std::ios::binary);
  std::string line;
  bool named = false;
  while (std::getline(in, line)) {
    const size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line.compare(start, 7, "mtllib ") != 0) continue;
    std::istringstream names(line.substr(start + 7));
    for (std::string name; names >> name;) {
      named = true;
      std::error_code ec;
      if (!std::filesystem::is_regular_file(folder / name, ec)) return false;
    }
  }
  return named;
}

class AssimpMeshBuilder {
 public:
  AssimpMeshBuilder(const aiScene& scene, const std::string& path, const ImportOptions& options)
      : scene_(scene), path_(path), options_(options), materialsFromFile_(materialLibraryFound(path)) {}

  ImportedMesh build() {
    imported_.mesh.materials = {unknownMaterial()};
    if (scene_.mRootNode) walk(*scene_.mRootNode, aiMatrix4x4());
    if (coloured_ == 0)
      fail(std::string("no vertex colours") +
           (withoutColours_ > 0 ? " (" + std::to_string(withoutColours_) + " mesh(es) without them)" : "") +
           ": radview reads B from per-vertex colours (OBJ: v x y z r g b)");
    if (withoutColours_ > 0)
      imported_.warnings.push_back(std::to_string(withoutColours_) + " mesh(es) without vertex colours skipped");
    if (repeatedCorners_ > 0)
      imported_.warnings.push_back(std::to_string(repeatedCorners_) +
                                   " face(s) with two corners at one vertex (one position and colour) dropped");
    if (pointsAndLines_ > 0)
      imported_.warnings.push_back(std::to_string(pointsAndLines_) + " point or line primitive(s) skipped");
    imported_.valueSource = "vertex colours (float), " + conversionName(false, options_.colours);
    imported_.reflectanceFromFile = materialsFromFile_ && !defaultMaterialUsed_;
    if (materialsFromFile_ && defaultMaterialUsed_)
      imported_.warnings.push_back("some faces have no material of the .mtl file: their reflectance is unknown");
    finishImportedMesh(imported_, path_);
    return std::move(imported_);
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw Error(path_, problem); }

  // Depth-first with an explicit stack: a deep file cannot overflow ours.
  void walk(const aiNode& root, const aiMatrix4x4& parent) {
    std::vector<std::pair<const aiNode*, aiMatrix4x4>> stack{{&root, parent}};
    while (!stack.empty()) {
      const auto [node, parentTransform] = stack.back();
      stack.pop_back();
      const aiMatrix4x4 transform = parentTransform * node->mTransformation;
      for (unsigned m = 0; m < node->mNumMeshes; ++m)
        if (node->mMeshes[m] < scene_.mNumMeshes) addMesh(*scene_.mMeshes[node->mMeshes[m]], transform);
      for (unsigned c = 0; c < node->mNumChildren; ++c) stack.push_back({node->mChildren[c], transform});
    }
  }

  void addMesh(const aiMesh& mesh, const aiMatrix4x4& transform) {
    if (!mesh.HasVertexColors(0)) {
      ++withoutColours_;
      return;
    }
    ++coloured_;
    std::vector<uint32_t> nodeOf(mesh.mNumVertices);
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D p = transform * mesh.mVertices[v];
      const aiColor4D& c = mesh.mColors[0][v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) fail("a vertex position is not finite");
      if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b))
        fail("the vertex at " + format(p) + " has colour " + format(c) + ", not finite numbers");
      const CornerKey key{{p.x, p.y, p.z, c.r, c.g, c.b}};
      const auto [at, added] = nodeIndex_.emplace(key, uint32_t(imported_.mesh.nodes.size()));
      if (added) {
        checkLimit(path_, imported_.mesh.nodes.size() + 1, kMaxSolutionNodes, "vertices");
        Node node;
        node.position = Vec3(p.x, p.y, p.z);
        node.B = Rgb(linearValue(c.r, 0.0, options_.colours), linearValue(c.g, 0.0, options_.colours),
                     linearValue(c.b, 0.0, options_.colours));
        imported_.mesh.nodes.push_back(node);
      }
      nodeOf[v] = at->second;
    }
    const int material = materialOf(mesh.mMaterialIndex);
    const bool mirrored = transform.Determinant() < 0.0f;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices < 3) {
        ++pointsAndLines_;
        continue;
      }
      checkLimit(path_, face.mNumIndices, kMaxElementCorners, "vertices in a face");
      checkLimit(path_, imported_.mesh.elements.size() + 1, kMaxSolutionElements, "faces");
      Element element;
      element.material = material;
      for (unsigned k = 0; k < face.mNumIndices; ++k) {
        if (face.mIndices[k] >= mesh.mNumVertices) fail("a face refers to a vertex that does not exist");
        element.corners.push_back(nodeOf[face.mIndices[k]]);
      }
      // Two corners joined into one node (the same vertex twice, or two vertices at one position
      // with one colour): no area between them.
      std::vector<uint32_t> sorted = element.corners;
      std::sort(sorted.begin(), sorted.end());
      if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
        ++repeatedCorners_;
        continue;
      }
      // A mirroring transform turns the winding round; turned back, the normal stays the face's.
      if (mirrored) std::reverse(element.corners.begin(), element.corners.end());
      imported_.mesh.elements.push_back(std::move(element));
    }
  }

  // The radview material of Assimp material `index`: from the OBJ's .mtl file, rho its Kd
  // (clamped to [0, 1]) and E its Ke; without one, the unknown material 0.
  int materialOf(unsigned index) {
    if (!materialsFromFile_ || index >= scene_.mNumMaterials) {
      defaultMaterialUsed_ = true;
      return 0;
    }
    const auto known = materialIndex_.find(index);
    if (known != materialIndex_.end()) return known->second;
    const aiMaterial& m = *scene_.mMaterials[index];
    aiString name;
    m.Get(AI_MATKEY_NAME, name);
    if (std::string(name.C_Str()) == AI_DEFAULT_MATERIAL_NAME) {
      defaultMaterialUsed_ = true;
      return materialIndex_[index] = 0;
    }
    aiColor3D diffuse(0.0f), emissive(0.0f);
    m.Get(AI_MATKEY_COLOR_DIFFUSE, diffuse);
    m.Get(AI_MATKEY_COLOR_EMISSIVE, emissive);
    const Rgb rho(diffuse.r, diffuse.g, diffuse.b), E(emissive.r, emissive.g, emissive.b);
    if (!isFinite(rho) || !isFinite(E)) fail(std::string("material ") + name.C_Str() + ": Kd or Ke is not finite");
    imported_.mesh.materials.push_back({name.C_Str(), glm::clamp(rho, 0.0, 1.0), glm::max(E, Rgb(0.0))});
    return materialIndex_[index] = int(imported_.mesh.materials.size()) - 1;
  }

  const aiScene& scene_;
  const std::string& path_;
  const ImportOptions& options_;
  const bool materialsFromFile_;
  bool defaultMaterialUsed_ = false;
  std::unordered_map<unsigned, int> materialIndex_;
  ImportedMesh imported_;
  std::unordered_map<CornerKey, uint32_t, CornerHash> nodeIndex_;
  size_t coloured_ = 0, withoutColours_ = 0, pointsAndLines_ = 0, repeatedCorners_ = 0;
};

}  // namespace

bool assimpReads(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext.empty() || ext == ".gltf" || ext == ".glb" || ext == ".ply") return false;
  return Assimp::Importer().IsExtensionSupported(ext);
}

ImportedMesh readAssimpMesh(const std::string& path, const ImportOptions& options) {
  checkInputFile(path, "a mesh file");
  // One importer per thread, kept: making one registers every format Assimp has, which costs
  // more than reading a small file. ReadFile frees the previous scene.
  thread_local Assimp::Importer importer;
  // No post-processing but Assimp's own consistency checks: no triangulation (quads stay
  // quads), no joining of vertices (done here, by position and colour only).
  const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
  if (!scene) throw Error(path, std::string("Assimp could not read it: ") + oneLine(importer.GetErrorString()));
  if (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) throw Error(path, "Assimp read it only in part (an incomplete scene)");
  ImportedMesh imported = AssimpMeshBuilder(*scene, path, options).build();
  importer.FreeScene();
  return imported;
}

}  // namespace radview
