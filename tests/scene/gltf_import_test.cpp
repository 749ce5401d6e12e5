// The glTF import over small files each test writes itself (tests/scene/gltf_test_files.h): what
// a well-formed file becomes. gltf_malformed_test.cpp: what a malformed one is refused with.
#include "scene/gltf_import.h"

#include "core/error.h"
#include "core/limits.h"
#include "geom/polygon.h"
#include "scene/gltf_document.h"
#include "tests/scene/gltf_test_files.h"
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

using test::GltfBuilder;
using test::GltfImportTest;
using test::str;

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

}  // namespace
}  // namespace radview
