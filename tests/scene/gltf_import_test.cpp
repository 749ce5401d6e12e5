// The glTF import over small files each test writes itself: what a well-formed file becomes,
// and that a malformed one gives an Error naming the file and the problem.
#include "scene/gltf_import.h"

#include "core/error.h"
#include "core/limits.h"
#include "geom/polygon.h"
#include "scene/gltf_document.h"
#include "tests/test_print.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace radview {
namespace {

namespace fs = std::filesystem;
using test::str;

// Builds a glTF model in memory: one buffer, one bufferView per accessor.
struct GltfBuilder {
  tinygltf::Model model;

  GltfBuilder() {
    model.buffers.emplace_back();
    model.asset.version = "2.0";
  }

  int view(const void* data, size_t size, size_t stride = 0) {
    std::vector<unsigned char>& bytes = model.buffers[0].data;
    bytes.resize((bytes.size() + 3) / 4 * 4);
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = bytes.size();
    v.byteLength = size;
    v.byteStride = stride;
    bytes.insert(bytes.end(), static_cast<const unsigned char*>(data), static_cast<const unsigned char*>(data) + size);
    model.bufferViews.push_back(v);
    return int(model.bufferViews.size()) - 1;
  }
  int accessor(int bufferView, int componentType, int type, size_t count) {
    tinygltf::Accessor a;
    a.bufferView = bufferView;
    a.componentType = componentType;
    a.type = type;
    a.count = count;
    model.accessors.push_back(a);
    return int(model.accessors.size()) - 1;
  }
  int positions(const std::vector<float>& xyz) {
    return accessor(view(xyz.data(), xyz.size() * 4), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
                    xyz.size() / 3);
  }
  template <typename T>
  int indices(const std::vector<T>& values) {
    const int type = sizeof(T) == 1   ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE
                     : sizeof(T) == 2 ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT
                                      : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    return accessor(view(values.data(), values.size() * sizeof(T)), type, TINYGLTF_TYPE_SCALAR, values.size());
  }
  int mesh(int positionAccessor, int indexAccessor = -1, int mode = TINYGLTF_MODE_TRIANGLES, int material = -1) {
    tinygltf::Primitive p;
    p.attributes["POSITION"] = positionAccessor;
    p.indices = indexAccessor;
    p.mode = mode;
    p.material = material;
    tinygltf::Mesh m;
    m.primitives.push_back(p);
    model.meshes.push_back(m);
    return int(model.meshes.size()) - 1;
  }
  int node(int meshIndex, std::vector<int> children = {}) {
    tinygltf::Node n;
    n.mesh = meshIndex;
    n.children = std::move(children);
    model.nodes.push_back(n);
    return int(model.nodes.size()) - 1;
  }
  int material(std::vector<double> baseColor, std::vector<double> emissive, double strength = -1.0) {
    tinygltf::Material m;
    m.name = "m" + std::to_string(model.materials.size());
    m.pbrMetallicRoughness.baseColorFactor = std::move(baseColor);
    m.emissiveFactor = std::move(emissive);
    if (strength >= 0.0) {
      m.extensions["KHR_materials_emissive_strength"] =
          tinygltf::Value(tinygltf::Value::Object{{"emissiveStrength", tinygltf::Value(strength)}});
      model.extensionsUsed.push_back("KHR_materials_emissive_strength");
    }
    model.materials.push_back(m);
    return int(model.materials.size()) - 1;
  }
  // A unit right triangle in z = 0 facing +Z, as a whole file: node 0 -> mesh 0.
  static GltfBuilder triangle() {
    GltfBuilder b;
    b.node(b.mesh(b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0})));
    return b;
  }

  void write(const std::string& path, bool binary = false) const {
    tinygltf::TinyGLTF writer;
    ASSERT_TRUE(writer.WriteGltfSceneToFile(&model, path, false, true, true, binary)) << path;
  }
};

class GltfImportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("radview_gltf_import_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  Scene import(const GltfBuilder& builder, std::vector<std::string>* warningsOut = nullptr) {
    const std::string file = path("scene.gltf");
    builder.write(file);
    const GltfDocument document(file);
    std::vector<std::string> warnings = document.warnings();
    Scene scene = importScene(document, warnings);
    if (warningsOut) *warningsOut = warnings;
    return scene;
  }

  // The Error message of opening and importing `file`; empty (a test failure) if none.
  std::string errorOf(const std::string& file) {
    try {
      const GltfDocument document(file);
      std::vector<std::string> warnings;
      importScene(document, warnings);
    } catch (const Error& e) {
      return e.what();
    }
    ADD_FAILURE() << file << " was accepted";
    return "";
  }
  std::string errorOf(const GltfBuilder& builder, const std::string& name = "bad.gltf") {
    builder.write(path(name));
    return errorOf(path(name));
  }
  // A triangle written as raw JSON, for what tinygltf's writer cannot express (it drops
  // minVersion and writes byteOffset as an int); its data in tri.bin.
  std::string rawTriangle(const std::string& name, const std::string& asset, const std::string& accessor) {
    const std::vector<float> xyz{0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::ofstream(path("tri.bin"), std::ios::binary).write(reinterpret_cast<const char*>(xyz.data()), 36);
    std::ofstream(path(name)) << R"({"asset": )" << asset << R"(,
      "buffers": [{"uri": "tri.bin", "byteLength": 36}], "bufferViews": [{"buffer": 0, "byteLength": 36}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", )"
                              << accessor << R"(}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "nodes": [{"mesh": 0}]})";
    return path(name);
  }
  void writeBytes(const std::string& name, const std::string& bytes) {
    std::ofstream(path(name), std::ios::binary) << bytes;
  }

  fs::path dir_;
};

// The message names the file and states the problem.
#define EXPECT_ERROR_NAMES(message, file, problem)                     \
  do {                                                                 \
    const std::string m_ = (message);                                  \
    EXPECT_NE(m_.find(file), std::string::npos) << m_;                 \
    EXPECT_NE(m_.find(problem), std::string::npos) << m_;              \
    EXPECT_EQ(m_.find('\n'), std::string::npos) << "one line: " << m_; \
  } while (0)

void expectNear(const Vec3& actual, const Vec3& expected) {
  EXPECT_NEAR(glm::distance(actual, expected), 0.0, 1e-6) << str(actual) << " vs " << str(expected);
}

TEST_F(GltfImportTest, TriangleBecomesOnePolygonWithTheDefaultMaterial) {
  const Scene scene = import(GltfBuilder::triangle());
  ASSERT_EQ(scene.polygons.size(), 1u);
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].rho, Rgb(1.0));  // glTF's default material: white, no emission
  EXPECT_EQ(scene.materials[0].E, Rgb(0.0));
  EXPECT_FALSE(scene.materials[0].name.empty());
  expectNear(unitNormal(scene.polygons[0].vertices), Vec3(0, 0, 1));
}

TEST_F(GltfImportTest, TrsTransformAppliesScaleThenRotationThenTranslation) {
  GltfBuilder b = GltfBuilder::triangle();
  b.model.nodes[0].translation = {10, 20, 30};
  b.model.nodes[0].rotation = {0, 0, std::sin(M_PI / 4), std::cos(M_PI / 4)};  // 90 degrees about +Z
  b.model.nodes[0].scale = {2, 3, 4};
  const Scene scene = import(b);
  ASSERT_EQ(scene.polygons.size(), 1u);
  // (1,0,0) -> scale (2,0,0) -> rotate (0,2,0) -> translate.
  expectNear(scene.polygons[0].vertices[1], Vec3(10, 22, 30));
  expectNear(scene.polygons[0].vertices[2], Vec3(7, 20, 30));
}

TEST_F(GltfImportTest, NestedNodesComposeMatrixAndTrs) {
  GltfBuilder b;
  const int child = b.node(b.mesh(b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0})));
  b.model.nodes[size_t(child)].translation = {1, 0, 0};
  b.node(-1, {child});
  // Parent: uniform scale 2, then translation (0,0,5), as a column-major matrix.
  b.model.nodes[1].matrix = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 5, 1};
  const Scene scene = import(b);
  ASSERT_EQ(scene.polygons.size(), 1u);
  expectNear(scene.polygons[0].vertices[0], Vec3(2, 0, 5));
  expectNear(scene.polygons[0].vertices[1], Vec3(4, 0, 5));
  expectNear(scene.polygons[0].vertices[2], Vec3(2, 2, 5));
}

TEST_F(GltfImportTest, DefaultSceneSelectsItsNodesOnly) {
  GltfBuilder b;
  const int tri = b.mesh(b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0}));
  b.node(tri);
  b.node(tri);
  b.model.nodes[1].translation = {0, 0, 7};
  tinygltf::Scene s;
  s.nodes = {1};
  b.model.scenes.push_back(s);
  b.model.defaultScene = 0;
  const Scene scene = import(b);
  ASSERT_EQ(scene.polygons.size(), 1u);
  EXPECT_EQ(scene.polygons[0].vertices[0].z, 7.0);
}

TEST_F(GltfImportTest, StripAndFanKeepEveryTriangleFacingFront) {
  // A 3x1 strip of quads in z = 0, top and bottom vertices alternating (8 vertices, 6
  // triangles), and a fan of 4 triangles around (0,0,1).
  GltfBuilder b;
  b.node(b.mesh(b.positions({0, 1, 0, 0, 0, 0, 1, 1, 0, 1, 0, 0, 2, 1, 0, 2, 0, 0, 3, 1, 0, 3, 0, 0}), -1,
                TINYGLTF_MODE_TRIANGLE_STRIP));
  b.node(b.mesh(b.positions({0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, -1, 1, 1, -1, 0, 1}), -1, TINYGLTF_MODE_TRIANGLE_FAN));
  const Scene scene = import(b);
  ASSERT_EQ(scene.polygons.size(), 10u);
  double total = 0.0;
  for (const Polygon& p : scene.polygons) {
    expectNear(unitNormal(p.vertices), Vec3(0, 0, 1));
    total += area(p.vertices);
  }
  EXPECT_NEAR(total, 3.0 + 2.0, 1e-12);
}

TEST_F(GltfImportTest, IndexedTrianglesWithEachIndexType) {
  GltfBuilder b;
  const int quad = b.positions({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
  b.node(b.mesh(quad, b.indices(std::vector<uint8_t>{0, 1, 2, 0, 2, 3})));
  b.node(b.mesh(quad, b.indices(std::vector<uint16_t>{0, 1, 2, 0, 2, 3})));
  b.node(b.mesh(quad, b.indices(std::vector<uint32_t>{0, 1, 2, 0, 2, 3})));
  const Scene scene = import(b);
  ASSERT_EQ(scene.polygons.size(), 6u);
  for (const Polygon& p : scene.polygons) EXPECT_NEAR(area(p.vertices), 0.5, 1e-12);
}

TEST_F(GltfImportTest, MaterialsTakeRhoFromBaseColorAndEmissionTimesStrength) {
  GltfBuilder b;
  const int pos = b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
  b.node(b.mesh(pos, -1, TINYGLTF_MODE_TRIANGLES, b.material({0.8, 0.5, 0.2, 1}, {1, 0.5, 0.25}, 10.0)));
  b.node(b.mesh(pos, -1, TINYGLTF_MODE_TRIANGLES, b.material({1.5, 0.5, -0.5, 1}, {0, 0, 0})));
  b.node(b.mesh(pos));  // no material: glTF's default
  std::vector<std::string> warnings;
  const Scene scene = import(b, &warnings);
  ASSERT_EQ(scene.materials.size(), 3u);
  EXPECT_EQ(scene.materials[0].name, "m0");
  EXPECT_EQ(scene.materials[0].rho, Rgb(0.8, 0.5, 0.2));
  EXPECT_EQ(scene.materials[0].E, Rgb(10, 5, 2.5));
  EXPECT_EQ(scene.materials[1].rho, Rgb(1.0, 0.5, 0.0));  // clamped to [0,1]
  EXPECT_EQ(scene.materials[2].rho, Rgb(1.0));
  EXPECT_EQ(scene.materials[2].E, Rgb(0.0));
  EXPECT_EQ(scene.emitters(), std::vector<int>{0});
  bool clampWarned = false;
  for (const std::string& w : warnings) clampWarned |= w.find("clamped") != std::string::npos;
  EXPECT_TRUE(clampWarned);
}

TEST_F(GltfImportTest, PerspectiveCameraLooksDownMinusZOfItsNode) {
  GltfBuilder b = GltfBuilder::triangle();
  tinygltf::Camera camera;
  camera.type = "perspective";
  camera.name = "front";
  camera.perspective.yfov = 0.7;
  camera.perspective.znear = 0.1;
  b.model.cameras.push_back(camera);
  tinygltf::Node n;
  n.camera = 0;
  n.translation = {1, 2, 3};
  n.rotation = {0, std::sin(M_PI / 4), 0, std::cos(M_PI / 4)};  // 90 degrees about +Y: -Z turns into -X
  b.model.nodes.push_back(n);
  const Scene scene = import(b);
  ASSERT_EQ(scene.cameras.size(), 1u);
  const SceneCamera& c = scene.cameras[0];
  EXPECT_EQ(c.name, "front");
  expectNear(c.eye, Vec3(1, 2, 3));
  expectNear(glm::normalize(c.target - c.eye), Vec3(-1, 0, 0));
  expectNear(c.up, Vec3(0, 1, 0));
  EXPECT_DOUBLE_EQ(c.yfov, 0.7);
}

TEST_F(GltfImportTest, MirroringTransformKeepsNormalsPointingOut) {
  // A triangle facing +Z, mirrored in X: still faces +Z, but its vertex order must flip.
  GltfBuilder b = GltfBuilder::triangle();
  b.model.nodes[0].scale = {-1, 1, 1};
  Scene scene = import(b);
  ASSERT_EQ(scene.polygons.size(), 1u);
  expectNear(unitNormal(scene.polygons[0].vertices), Vec3(0, 0, 1));
  // Mirrored by a matrix in Z: a triangle facing +Z now faces -Z.
  b.model.nodes[0].scale.clear();
  b.model.nodes[0].matrix = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1};
  scene = import(b);
  expectNear(unitNormal(scene.polygons[0].vertices), Vec3(0, 0, -1));
}

TEST_F(GltfImportTest, PointsLinesAndDegenerateTrianglesAreSkippedWithWarnings) {
  GltfBuilder b = GltfBuilder::triangle();
  const int pos = b.positions({0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 5, 5, 5});  // collinear, then repeated
  b.node(b.mesh(pos, -1, TINYGLTF_MODE_POINTS));
  b.node(b.mesh(pos, -1, TINYGLTF_MODE_LINE));
  b.node(b.mesh(pos));
  std::vector<std::string> warnings;
  const Scene scene = import(b, &warnings);
  EXPECT_EQ(scene.polygons.size(), 1u);
  std::string all;
  for (const std::string& w : warnings) all += w + "\n";
  EXPECT_NE(all.find("1 POINTS primitive(s) skipped"), std::string::npos) << all;
  EXPECT_NE(all.find("1 LINES primitive(s) skipped"), std::string::npos) << all;
  EXPECT_NE(all.find("2 degenerate (zero-area) triangle(s) dropped"), std::string::npos) << all;
}

TEST_F(GltfImportTest, SparseAccessorOverridesBaseValues) {
  GltfBuilder b = GltfBuilder::triangle();
  const std::vector<uint16_t> which{2};
  const std::vector<float> value{0, 5, 0};
  tinygltf::Accessor& a = b.model.accessors[0];
  a.sparse.isSparse = true;
  a.sparse.count = 1;
  a.sparse.indices.bufferView = b.view(which.data(), 2);
  a.sparse.indices.byteOffset = 0;
  a.sparse.indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  a.sparse.values.bufferView = b.view(value.data(), 12);
  a.sparse.values.byteOffset = 0;
  const Scene scene = import(b);
  ASSERT_EQ(scene.polygons.size(), 1u);
  expectNear(scene.polygons[0].vertices[2], Vec3(0, 5, 0));
}

TEST_F(GltfImportTest, QuantizedPositionsAreDecodedPerSpec) {
  GltfBuilder b;
  const std::vector<int16_t> xyz{0, 0, 0, 32767, 0, 0, 0, -32768, 0};  // normalized: -32768 -> -1
  b.node(
      b.mesh(b.accessor(b.view(xyz.data(), xyz.size() * 2, 8), TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_TYPE_VEC3, 3)));
  b.model.accessors[0].normalized = true;
  b.model.extensionsUsed = {"KHR_mesh_quantization"};
  b.model.extensionsRequired = {"KHR_mesh_quantization"};
  // Stride 8 needs 8 bytes per element in the view: pad the last element.
  b.model.bufferViews[0].byteLength = 3 * 8;
  b.model.buffers[0].data.resize(3 * 8);
  const std::vector<int16_t> padded{0, 0, 0, 0, 32767, 0, 0, 0, 0, -32768, 0, 0};
  std::memcpy(b.model.buffers[0].data.data(), padded.data(), 24);
  const Scene scene = import(b);
  ASSERT_EQ(scene.polygons.size(), 1u);
  expectNear(scene.polygons[0].vertices[1], Vec3(1, 0, 0));
  expectNear(scene.polygons[0].vertices[2], Vec3(0, -1, 0));
}

TEST_F(GltfImportTest, BinaryGlbLoadsLikeGltf) {
  GltfBuilder::triangle().write(path("triangle.glb"), true);
  const GltfDocument document(path("triangle.glb"));
  std::vector<std::string> warnings;
  EXPECT_EQ(importScene(document, warnings).polygons.size(), 1u);
}

// --- malformed input ---------------------------------------------------------------------

TEST_F(GltfImportTest, MissingFileDirectoryEmptyAndUnknownExtension) {
  EXPECT_ERROR_NAMES(errorOf(path("absent.gltf")), "absent.gltf", "no such file");
  fs::create_directories(path("folder.gltf"));
  EXPECT_ERROR_NAMES(errorOf(path("folder.gltf")), "folder.gltf", "is a directory");
  writeBytes("empty.glb", "");
  EXPECT_ERROR_NAMES(errorOf(path("empty.glb")), "empty.glb", "the file is empty");
  writeBytes("scene.obj", "v 0 0 0\n");
  EXPECT_ERROR_NAMES(errorOf(path("scene.obj")), "scene.obj", "unknown file type \".obj\"");
}

TEST_F(GltfImportTest, GarbageBytesAreRefused) {
  std::string garbage;
  for (int i = 0; i < 256; ++i) garbage += char((i * 151 + 7) & 0xff);
  writeBytes("garbage.gltf", garbage);
  writeBytes("garbage.glb", garbage);
  writeBytes("truncated.glb", std::string("glTF\x02\0\0\0", 8));
  for (const char* name : {"garbage.gltf", "garbage.glb", "truncated.glb"}) {
    const std::string message = errorOf(path(name));
    EXPECT_NE(message.find(name), std::string::npos) << message;
    EXPECT_GT(message.size(), path(name).size() + 2) << "a reason follows the file name: " << message;
  }
}

// A GLB whose buffer 0 (no uri, so the BIN chunk) declares byteLength 0 beside a 4-byte BIN
// chunk: tinygltf indexes an empty vector with at() and throws std::out_of_range. Found by the
// glTF fuzz target; the same bytes are kept in tests/fuzz/regressions/gltf/.
TEST_F(GltfImportTest, BinChunkBesideAnEmptyBufferIsRefused) {
  const std::string json =
      R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":0,"ur_":"data:application/gltf-buffer,0"}]} )";
  const auto le32 = [](uint32_t v) { return std::string{char(v), char(v >> 8), char(v >> 16), char(v >> 24)}; };
  const std::string bin = "\xff\xff\xff\xff";
  const std::string bytes = "glTF" + le32(2) + le32(uint32_t(12 + 8 + json.size() + 8 + bin.size())) +
                            le32(uint32_t(json.size())) + "JSON" + json + le32(uint32_t(bin.size())) +
                            std::string("BIN\0", 4) + bin;
  writeBytes("empty_buffer.glb", bytes);
  const std::string message = errorOf(path("empty_buffer.glb"));
  EXPECT_NE(message.find("empty_buffer.glb"), std::string::npos) << message;
  EXPECT_NE(message.find("malformed"), std::string::npos) << message;
}

TEST_F(GltfImportTest, AccessorOutOfRange) {
  GltfBuilder b = GltfBuilder::triangle();
  b.model.meshes[0].primitives[0].attributes["POSITION"] = 7;
  EXPECT_ERROR_NAMES(errorOf(b), "bad.gltf", "mesh 0 primitive 0 POSITION: accessor 7 does not exist");
}

TEST_F(GltfImportTest, IndexPastVertexCount) {
  GltfBuilder b;
  const int positions = b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
  b.node(b.mesh(positions, b.indices(std::vector<uint16_t>{0, 1, 3})));
  EXPECT_ERROR_NAMES(errorOf(b), "bad.gltf", "mesh 0 primitive 0 indices: accessor 1: element 2 is 3, out of range");
}

TEST_F(GltfImportTest, PrimitiveRestartIndexIsRefused) {
  GltfBuilder b;
  const int positions = b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
  b.node(b.mesh(positions, b.indices(std::vector<uint8_t>{0, 1, 255})));
  EXPECT_ERROR_NAMES(errorOf(b), "bad.gltf", "primitive-restart value 255");
}

TEST_F(GltfImportTest, NanPositionIsRefused) {
  GltfBuilder b;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  b.node(b.mesh(b.positions({0, 0, 0, 1, nan, 0, 0, 1, 0})));
  EXPECT_ERROR_NAMES(errorOf(b), "bad.gltf", "POSITION: accessor 0: element 1 is not finite");
}

TEST_F(GltfImportTest, BufferViewPastEndOfBuffer) {
  GltfBuilder b = GltfBuilder::triangle();
  b.model.bufferViews[0].byteLength = 400;
  b.model.buffers[0].data.resize(400);    // the writer's byteLength; the view starts at 0 and fits...
  b.model.bufferViews[0].byteOffset = 4;  // ...until it starts 4 bytes in
  EXPECT_ERROR_NAMES(errorOf(b), "bad.gltf",
                     "bufferView 0 (byteOffset 4, byteLength 400) runs past the end of buffer 0");
}

TEST_F(GltfImportTest, AccessorPastEndOfBufferView) {
  GltfBuilder b = GltfBuilder::triangle();
  b.model.accessors[0].count = 4;
  EXPECT_ERROR_NAMES(errorOf(b), "bad.gltf", "run past the end of bufferView 0");
}

// Counts and offsets near 2^64 (written as raw JSON: tinygltf's writer stores them as int) must
// not wrap around into a range that looks valid; a count past radview's limit is refused before
// anything is read or allocated.
TEST_F(GltfImportTest, HugeCountsAndOffsetsDoNotWrapAround) {
  const std::string asset = R"({"version": "2.0"})";
  EXPECT_ERROR_NAMES(errorOf(rawTriangle("count.gltf", asset, R"("count": 1537228672809129302)")), "count.gltf",
                     "accessor 0: count 1537228672809129302, more than radview's limit of 67108864");
  EXPECT_ERROR_NAMES(errorOf(rawTriangle("offset.gltf", asset, R"("count": 3, "byteOffset": 18446744073709551612)")),
                     "offset.gltf", "run past the end of bufferView 0");
}

// A hostile file: 36 bytes of data, accessors that declare billions of elements. Each is
// refused by its limit (core/limits.h) with the file, the accessor and the limit named, at once.
TEST_F(GltfImportTest, DeclaredCountsPastTheLimitsAreRefusedBeforeAnyAllocation) {
  const std::string asset = R"({"version": "2.0"})";
  EXPECT_ERROR_NAMES(errorOf(rawTriangle("huge.gltf", asset, R"("count": 3000000000)")), "huge.gltf",
                     "POSITION: accessor 0: count 3000000000, more than radview's limit of 67108864 elements");
  // Within the accessor limit but past the data: the data bounds it.
  EXPECT_ERROR_NAMES(errorOf(rawTriangle("past.gltf", asset, R"("count": 67108864)")), "past.gltf",
                     "67108864 elements of 12 bytes, stride 12, from byte 0 run past the end of bufferView 0");
  // No bufferView: zeros that cost memory and no file bytes, so a lower limit.
  GltfBuilder zeros = GltfBuilder::triangle();
  zeros.model.accessors[0].bufferView = -1;
  zeros.model.accessors[0].count = 20'000'000;
  EXPECT_ERROR_NAMES(errorOf(zeros, "zeros.gltf"), "zeros.gltf",
                     "has no bufferView and a count of 20000000, more than radview's limit of 16777216");
}

// A small file that instances one mesh many times: the scene's triangle limit counts
// instances, so 1,000 triangles on 2,001 nodes (a 36 KB buffer) are refused.
TEST_F(GltfImportTest, InstancedTrianglesPastTheSceneLimitAreRefused) {
  GltfBuilder b;
  std::vector<float> xyz;
  for (int i = 0; i < 1000; ++i)
    xyz.insert(xyz.end(), {float(i), 0.f, 0.f, float(i) + 0.5f, 0.f, 0.f, float(i), 1.f, 0.f});
  const int mesh = b.mesh(b.positions(xyz));
  for (int n = 0; n < 2001; ++n) b.node(mesh);
  static_assert(kMaxSceneTriangles == 2'000'000, "the file above is sized for this limit");
  EXPECT_ERROR_NAMES(errorOf(b, "instanced.gltf"), "instanced.gltf",
                     "more than 2000000 triangles after instancing; radview does not mesh scenes that large");
}

TEST_F(GltfImportTest, StrideSmallerThanElementIsRefused) {
  GltfBuilder b = GltfBuilder::triangle();
  b.model.bufferViews[0].byteStride = 8;
  EXPECT_ERROR_NAMES(errorOf(b), "bad.gltf", "byteStride 8, smaller than the element size 12");
}

TEST_F(GltfImportTest, WrongComponentTypeForPositions) {
  GltfBuilder b;
  const std::vector<uint16_t> xyz{0, 0, 0, 1, 0, 0, 0, 1, 0};
  b.node(b.mesh(b.accessor(b.view(xyz.data(), 18), TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC3, 3)));
  EXPECT_ERROR_NAMES(errorOf(b), "bad.gltf", "component type UNSIGNED_SHORT is not allowed here (allowed: FLOAT)");
}

TEST_F(GltfImportTest, NodeCycleAndSharedChildAreRefused) {
  GltfBuilder b = GltfBuilder::triangle();
  b.node(-1, {2});
  b.node(-1, {1});  // 1 -> 2 -> 1
  EXPECT_ERROR_NAMES(errorOf(b), "bad.gltf", "its own ancestor");
  GltfBuilder shared = GltfBuilder::triangle();
  shared.node(-1, {0});
  shared.node(-1, {0});
  EXPECT_ERROR_NAMES(errorOf(shared, "shared.gltf"), "shared.gltf", "node 0 has two parents");
}

TEST_F(GltfImportTest, AbsurdlyDeepHierarchyIsRefused) {
  GltfBuilder b = GltfBuilder::triangle();
  for (int i = 0; i < 2000; ++i) b.node(-1, {int(b.model.nodes.size()) - 1});
  EXPECT_ERROR_NAMES(errorOf(b), "bad.gltf", "deeper than 1024 levels");
}

TEST_F(GltfImportTest, UnsupportedVersionsAndRequiredExtensionsAreRefused) {
  const std::string count = R"("count": 3)";
  EXPECT_ERROR_NAMES(errorOf(rawTriangle("min.gltf", R"({"version": "2.1", "minVersion": "2.1"})", count)), "min.gltf",
                     "requires glTF 2.1");
  EXPECT_ERROR_NAMES(errorOf(rawTriangle("minmax.gltf", R"({"version": "2.0", "minVersion": "2.1"})", count)),
                     "minmax.gltf", "asset.minVersion 2.1 is greater than asset.version 2.0");
  EXPECT_ERROR_NAMES(errorOf(rawTriangle("old.gltf", R"({"version": "1.0"})", count)), "old.gltf",
                     "radview reads glTF 2.x only");
  EXPECT_ERROR_NAMES(errorOf(rawTriangle("empty.gltf", R"({"version": ""})", count)), "empty.gltf",
                     "asset.version is missing");
  // A newer minor version without minVersion is meant to load in a 2.0 reader.
  const GltfDocument newer(rawTriangle("newer.gltf", R"({"version": "2.7"})", count));
  GltfBuilder b = GltfBuilder::triangle();
  b.model.extensionsUsed = {"KHR_draco_mesh_compression"};
  b.model.extensionsRequired = {"KHR_draco_mesh_compression"};
  EXPECT_ERROR_NAMES(errorOf(b, "draco.gltf"), "draco.gltf", "requires extension KHR_draco_mesh_compression");
}

TEST_F(GltfImportTest, MaterialOutOfRangeAndBadEmissiveStrength) {
  GltfBuilder b = GltfBuilder::triangle();
  b.model.meshes[0].primitives[0].material = 3;
  EXPECT_ERROR_NAMES(errorOf(b), "bad.gltf", "material 3 does not exist");
  b.model.meshes[0].primitives[0].material = b.material({1, 1, 1, 1}, {1, 1, 1}, 1.0);
  b.model.materials[0].extensions["KHR_materials_emissive_strength"] =
      tinygltf::Value(tinygltf::Value::Object{{"emissiveStrength", tinygltf::Value(-2.0)}});
  EXPECT_ERROR_NAMES(errorOf(b, "strength.gltf"), "strength.gltf", "emissiveStrength is not a finite number >= 0");
}

TEST_F(GltfImportTest, NothingDrawableIsAnError) {
  GltfBuilder b;
  b.node(b.mesh(b.positions({0, 0, 0, 1, 0, 0}), -1, TINYGLTF_MODE_LINE));
  EXPECT_ERROR_NAMES(errorOf(b), "bad.gltf", "no triangles to show");
}

}  // namespace
}  // namespace radview
