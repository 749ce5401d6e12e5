// Malformed glTF files, each written by its test (tests/scene/gltf_test_files.h): every one is
// refused with an Error naming the file and the problem, before anything past radview's limits
// (core/limits.h) is read or allocated.
#include "scene/gltf_import.h"

#include "core/error.h"
#include "core/limits.h"
#include "tests/scene/gltf_test_files.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

namespace radview {
namespace {

using test::GltfBuilder;
using test::GltfImportTest;

TEST_F(GltfImportTest, MissingFileDirectoryEmptyAndUnknownExtension) {
  EXPECT_ERROR_NAMES(errorOf(path("absent.gltf")), "absent.gltf", "no such file");
  std::filesystem::create_directories(path("folder.gltf"));
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
