#include "tests/fuzz/fuzz_inputs.h"

#include "core/camera.h"
#include "core/error.h"
#include "core/npy_array.h"
#include "import/load_file.h"
#include "import/ply_file.h"
#include "import/ply_mesh.h"
#include "interp/interpolant.h"
#include "interp/t_vertex_repair.h"
#include "mesh/display_mesh.h"
#include "mesh/topology.h"
#include "scene/camera_presets.h"
#include "solve/direct_light.h"
#include "tests/fuzz/mesh_bytes.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

namespace radview::fuzz {

namespace {

namespace fs = std::filesystem;

// One directory per process (libFuzzer's parallel jobs are processes), removed at exit so
// that test runs leave nothing in the temporary directory.
class PrivateDirectory {
 public:
  PrivateDirectory() : path_(fs::temp_directory_path() / ("radview-fuzz-" + std::to_string(::getpid()))) {
    fs::create_directories(path_);
  }
  ~PrivateDirectory() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

const fs::path& privateDirectory() {
  static const PrivateDirectory directory;
  return directory.path();
}

bool finite(const Sample& s) {
  bool ok = std::isfinite(s.B.r) && std::isfinite(s.B.g) && std::isfinite(s.B.b);
  for (const Vec3& g : s.gradient) ok = ok && std::isfinite(g.x) && std::isfinite(g.y) && std::isfinite(g.z);
  return ok;
}

Vec3 cornerMean(const RadiosityMesh& mesh, size_t element) {
  Vec3 sum(0.0);
  for (uint32_t corner : mesh.elements[element].corners) sum += mesh.nodes[corner].position;
  return sum / double(mesh.elements[element].corners.size());
}

}  // namespace

void exerciseMesh(const RadiosityMesh& mesh) {
  const MeshTopology topology(mesh);
  const DisplayMesh display = buildDisplayMesh(mesh, topology);
  const std::vector<DisplayVertex> triangles = displayTriangles(mesh, topology);
  const RadiosityMesh repaired = repairTVertices(mesh);
  // The view-dependent methods seen from the front preset, 64x64 pixels.
  InterpolantOptions options;
  const Camera camera = cameraFromSpec("front", mesh.bounds(), {});
  options.view = ScreenView{camera.clipFromWorld(1.0), Vec2(64.0)};
  for (const MethodInfo& method : methodRegistry()) {
    const std::unique_ptr<Interpolant> interpolant = makeInterpolant(mesh, method.method, options);
    for (size_t e = 0; e < mesh.elements.size(); ++e) {
      const Sample s = interpolant->evaluate(uint32_t(e), cornerMean(mesh, e));
      if (!finite(s)) {
        std::fprintf(stderr, "fuzz: %s interpolant is not finite at element %zu\n", method.name.c_str(), e);
        std::abort();
      }
    }
  }
}

bool openGltfBytes(const uint8_t* data, size_t size) {
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const fs::path path = privateDirectory() / (binary ? "input.glb" : "input.gltf");
  {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    if (!file) {
      std::fprintf(stderr, "fuzz: cannot write %s\n", path.c_str());
      std::abort();
    }
  }
  try {
    const LoadedFile loaded = loadFile(path.string());
    if (loaded.isSolution) {
      exerciseMesh(loaded.mesh);
    } else {
      // Coarse, so that one input stays fast: about 8 elements along the scene's diagonal.
      const Bounds bounds = loaded.scene.bounds();
      if (bounds.empty()) return true;
      exerciseMesh(meshAndLight(loaded.scene, glm::length(bounds.extent()) / 8.0));
    }
    return true;
  } catch (const Error&) {
    return false;
  }
}

bool importMeshBytes(const uint8_t* data, size_t size) {
  try {
    if (size >= 3 && std::memcmp(data, "ply", 3) == 0) {
      const std::vector<char> bytes(data, data + size);
      exerciseMesh(plyMesh(parsePly(bytes, "input.ply"), "input.ply", {}).mesh);
      return true;
    }
    const fs::path path = privateDirectory() / "input.obj";
    {
      std::ofstream file(path, std::ios::binary | std::ios::trunc);
      file.write(reinterpret_cast<const char*>(data), std::streamsize(size));
      if (!file) {
        std::fprintf(stderr, "fuzz: cannot write %s\n", path.c_str());
        std::abort();
      }
    }
    exerciseMesh(loadFile(path.string()).mesh);
    return true;
  } catch (const Error&) {
    return false;
  }
}

bool parseNpyBytes(const uint8_t* data, size_t size) {
  try {
    const NpyMatrix matrix = parseNpy(reinterpret_cast<const char*>(data), size, "input.npy");
    if (matrix.values.size() != matrix.rows * matrix.columns) {
      std::fprintf(stderr, "fuzz: %zu numbers for a %zu x %zu array\n", matrix.values.size(), matrix.rows,
                   matrix.columns);
      std::abort();
    }
    return true;
  } catch (const Error&) {
    return false;
  }
}

bool buildMeshBytes(const uint8_t* data, size_t size) {
  const RadiosityMesh mesh = decodeMesh(data, size);
  try {
    validateMesh(mesh, "fuzz input");
    exerciseMesh(mesh);
    return true;
  } catch (const Error&) {
    return false;
  }
}

}  // namespace radview::fuzz
