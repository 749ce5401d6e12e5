// Solution files: a radiosity mesh survives writing and reading (as .glb and .gltf), other
// viewers see a proper glTF scene, and damaged files give clear Errors.
#include "mesh/solution_file.h"

#include "core/error.h"
#include "core/limits.h"
#include "geom/polygon.h"
#include "import/load_file.h"
#include "scene/gltf_document.h"
#include "scene/gltf_import.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>

namespace radview {
namespace {

namespace fs = std::filesystem;

// A small mesh with every feature of the format, all in the z = 0 plane facing +Z:
//   element 0  concave L hexagon (nodes 0-5), material 0, surface 3
//   element 1  quadratic triangle (corners 6-8, mid-edge 9-11), material 0, surface unknown
//   element 2  emitting quad (nodes 1, 12, 13, 2), material 1: nodes 1 and 2 border two
//              materials, so they are stored in both primitives
//   element 3  quadratic concave dart (corners 18-21, mid-edge 22-25), material 0, surface 7
//   element 4  triangle (nodes 14-16) across a C-1 edge from element 0: nodes 14 and 15 sit on
//              nodes 3 and 2 with other values
//   node 17    used by no element
// Material 2 is used by no element. Discontinuity edges of all three orders. Standard errors,
// 0 at every third node.
RadiosityMesh sampleMesh() {
  RadiosityMesh mesh;
  mesh.materials = {{"white", Rgb(0.7), Rgb(0.0)},
                    {"light", Rgb(0.8), Rgb(12.5, 10.0, 7.5)},
                    {"unused", Rgb(0.1, 0.2, 0.3), Rgb(0.0)}};
  const std::vector<Vec2> xy = {{0, 0},      {2, 0},      {2, 1},   {1, 1},  {1, 2}, {0, 2},  // 0-5  L
                                {4, 0},      {6, 0},      {4, 2},   {5, 0},  {5, 1}, {4, 1},  // 6-11 quadratic triangle
                                {3, 0},      {3, 1},                                          // 12-13 emitter
                                {1, 1},      {2, 1},      {2, 2},               // 14-16 across the C-1 edge
                                {9, 9},                                         // 17 orphan
                                {0, 3},      {1, 3.5},    {2, 3},   {1, 5},     // 18-21 dart corners
                                {0.5, 3.25}, {1.5, 3.25}, {1.5, 4}, {0.5, 4}};  // 22-25 dart mid-edges
  for (size_t i = 0; i < xy.size(); ++i) {
    Node n;
    n.position = Vec3(xy[i], 0.0) + Vec3(0.1, 0.2, 0.3);
    n.B = Rgb(0.1 * double(i), 0.05 * double(i) + 0.01, 1.0 / (1.0 + double(i)));
    n.gradient = {Vec3(0.01 * double(i), 1, 0), Vec3(0, 2, -0.5), Vec3(1e-3, 0, 3)};
    n.standardError = i % 3 == 0 ? Rgb(0.0) : Rgb(1e-3 * double(i), 2e-3, 0.5e-3 * double(i));
    mesh.nodes.push_back(n);
  }
  for (uint32_t n : {12u, 13u}) mesh.nodes[n].B = Rgb(12.5, 10.0, 7.5);
  mesh.hasGradients = true;
  mesh.hasStandardErrors = true;
  mesh.elements = {{{0, 1, 2, 3, 4, 5}, {}, 0, 3},
                   {{6, 7, 8}, {9, 10, 11}, 0, -1},
                   {{1, 12, 13, 2}, {}, 1, 5},
                   {{18, 19, 20, 21}, {22, 23, 24, 25}, 0, 7},
                   {{14, 15, 16}, {}, 0, 2}};
  mesh.discontinuities = {{3, 2, Continuity::Cm1}, {0, 1, Continuity::C0}, {7, 8, Continuity::C1}};
  validateMesh(mesh, "sampleMesh");
  return mesh;
}

// v rounded to float32, as the file stores it. Through volatile because GCC 12.2 at -O2/-O3 (SLP
// vectorizer) folds a two-lane double -> float -> double round trip into a plain copy.
double toFloat(double x) {
  volatile float f = float(x);
  return f;
}
Vec3 toFloat(const Vec3& v) { return Vec3(toFloat(v.x), toFloat(v.y), toFloat(v.z)); }

void expectSameMesh(const RadiosityMesh& written, const RadiosityMesh& read) {
  ASSERT_EQ(read.nodes.size(), written.nodes.size());
  for (size_t i = 0; i < written.nodes.size(); ++i) {
    SCOPED_TRACE("node " + std::to_string(i));
    EXPECT_EQ(read.nodes[i].position, toFloat(written.nodes[i].position));
    EXPECT_EQ(read.nodes[i].B, toFloat(written.nodes[i].B));
    for (size_t c = 0; c < 3; ++c)
      EXPECT_EQ(read.nodes[i].gradient[c], written.hasGradients ? toFloat(written.nodes[i].gradient[c]) : Vec3(0.0));
    EXPECT_EQ(read.nodes[i].standardError,
              written.hasStandardErrors ? toFloat(written.nodes[i].standardError) : Rgb(0.0));
  }
  ASSERT_EQ(read.elements.size(), written.elements.size());
  for (size_t e = 0; e < written.elements.size(); ++e) {
    SCOPED_TRACE("element " + std::to_string(e));
    EXPECT_EQ(read.elements[e].corners, written.elements[e].corners);
    EXPECT_EQ(read.elements[e].midEdge, written.elements[e].midEdge);
    EXPECT_EQ(read.elements[e].material, written.elements[e].material);
    EXPECT_EQ(read.elements[e].surface, written.elements[e].surface);
  }
  ASSERT_EQ(read.materials.size(), written.materials.size());
  for (size_t m = 0; m < written.materials.size(); ++m) {
    EXPECT_EQ(read.materials[m].name, written.materials[m].name);
    EXPECT_EQ(read.materials[m].rho, written.materials[m].rho);
    EXPECT_EQ(read.materials[m].E, written.materials[m].E);
  }
  ASSERT_EQ(read.discontinuities.size(), written.discontinuities.size());
  for (size_t d = 0; d < written.discontinuities.size(); ++d) {
    EXPECT_EQ(read.discontinuities[d].a, written.discontinuities[d].a);
    EXPECT_EQ(read.discontinuities[d].b, written.discontinuities[d].b);
    EXPECT_EQ(read.discontinuities[d].order, written.discontinuities[d].order);
  }
  EXPECT_EQ(read.hasGradients, written.hasGradients);
  EXPECT_EQ(read.hasStandardErrors, written.hasStandardErrors);
}

class SolutionFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("radview_solution_file_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // Writes the sample mesh, lets `change` damage the file's model, and writes that as `name`.
  std::string damaged(const std::string& name, const std::function<void(tinygltf::Model&)>& change) {
    writeSolution(sampleMesh(), path("good.gltf"));
    tinygltf::Model model;
    tinygltf::TinyGLTF gltf;
    std::string err, warn;
    EXPECT_TRUE(gltf.LoadASCIIFromFile(&model, &err, &warn, path("good.gltf"))) << err;
    change(model);
    EXPECT_TRUE(gltf.WriteGltfSceneToFile(&model, path(name), false, true, true, false));
    return path(name);
  }
  std::string readError(const std::string& file) {
    try {
      readSolution(GltfDocument(file));
    } catch (const Error& e) {
      return e.what();
    }
    ADD_FAILURE() << file << " was accepted";
    return "";
  }

  fs::path dir_;
};

// The accessor a property of the first primitive's extension names, and its data.
tinygltf::Value::Object& firstPrimitiveExtension(tinygltf::Model& model) {
  return model.meshes[0].primitives[0].extensions[kSolutionExtension].Get<tinygltf::Value::Object>();
}
unsigned char* accessorBytes(tinygltf::Model& model, int accessor) {
  const tinygltf::Accessor& a = model.accessors[size_t(accessor)];
  const tinygltf::BufferView& v = model.bufferViews[size_t(a.bufferView)];
  return model.buffers[size_t(v.buffer)].data.data() + v.byteOffset + a.byteOffset;
}
void setUint(tinygltf::Model& model, const char* property, size_t element, uint32_t value) {
  const int accessor = firstPrimitiveExtension(model)[property].GetNumberAsInt();
  std::memcpy(accessorBytes(model, accessor) + 4 * element, &value, 4);
}

TEST_F(SolutionFileTest, RoundTripThroughGlbAndGltf) {
  const RadiosityMesh mesh = sampleMesh();
  for (const char* name : {"solution.glb", "solution.gltf", "SOLUTION.GLB"}) {
    SCOPED_TRACE(name);
    writeSolution(mesh, path(name));
    const GltfDocument document(path(name));
    ASSERT_TRUE(isSolution(document));
    expectSameMesh(mesh, readSolution(document));
  }
}

TEST_F(SolutionFileTest, RoundTripWithoutGradientsStandardErrorsOrDiscontinuities) {
  RadiosityMesh mesh = sampleMesh();
  mesh.hasGradients = false;
  mesh.hasStandardErrors = false;
  mesh.discontinuities.clear();
  writeSolution(mesh, path("plain.glb"));
  const GltfDocument document(path("plain.glb"));
  for (const tinygltf::Primitive& p : document.model().meshes[0].primitives)
    EXPECT_EQ(p.attributes.count("_RADIOSITY_STANDARD_ERROR"), 0u);
  EXPECT_FALSE(document.model().extensions.at(kSolutionExtension).Has("hasStandardErrors"));
  const RadiosityMesh read = readSolution(document);
  EXPECT_FALSE(read.hasGradients);
  EXPECT_FALSE(read.hasStandardErrors);
  expectSameMesh(mesh, read);
  EXPECT_TRUE(read.discontinuities.empty());
  EXPECT_EQ(read.elements[3].midEdge, mesh.elements[3].midEdge);
}

TEST_F(SolutionFileTest, CMinus1EdgeKeepsItsDuplicatedNodes) {
  const RadiosityMesh mesh = sampleMesh();
  writeSolution(mesh, path("c-1.glb"));
  const RadiosityMesh read = readSolution(GltfDocument(path("c-1.glb")));
  // Nodes 3/14 and 2/15 share positions but not values, and stay distinct nodes.
  EXPECT_EQ(read.nodes[3].position, read.nodes[14].position);
  EXPECT_EQ(read.nodes[2].position, read.nodes[15].position);
  EXPECT_NE(read.nodes[3].B, read.nodes[14].B);
  EXPECT_EQ(read.elements[4].corners, (std::vector<uint32_t>{14, 15, 16}));
  EXPECT_EQ(read.discontinuities[0].order, Continuity::Cm1);
}

TEST_F(SolutionFileTest, LoadFileRecognizesASolution) {
  writeSolution(sampleMesh(), path("loaded.glb"));
  const LoadedFile loaded = loadFile(path("loaded.glb"));
  EXPECT_TRUE(loaded.isSolution);
  EXPECT_TRUE(loaded.scene.polygons.empty());
  expectSameMesh(sampleMesh(), loaded.mesh);
  EXPECT_TRUE(loaded.warnings.empty()) << loaded.warnings.front();
}

// The scene's cameras ride along as standard glTF cameras: loadFile gives them back (so a
// solved scene opens where its author looked from), another viewer reads them as the
// scene import does, and clip planes are valid glTF (0 < znear < zfar).
TEST_F(SolutionFileTest, CamerasRoundTripAsGltfCameras) {
  const std::vector<SceneCamera> cameras{
      {"front", Vec3(0.5, 0.25, 3.0), Vec3(0.5, 0.25, 0.0), Vec3(0.0, 1.0, 0.0), glm::radians(40.0)},
      {"tilted", Vec3(-2.0, 1.0, 1.5), Vec3(0.3, 0.2, 0.0), Vec3(0.2, 0.1, 1.0), glm::radians(70.0)}};
  writeSolution(sampleMesh(), path("cameras.glb"), cameras);
  const LoadedFile loaded = loadFile(path("cameras.glb"));
  EXPECT_TRUE(loaded.warnings.empty()) << loaded.warnings.front();
  ASSERT_EQ(loaded.scene.cameras.size(), 2u);
  for (size_t c = 0; c < cameras.size(); ++c) {
    SCOPED_TRACE(cameras[c].name);
    const SceneCamera& read = loaded.scene.cameras[c];
    EXPECT_EQ(read.name, cameras[c].name);
    EXPECT_NEAR(glm::distance(read.eye, cameras[c].eye), 0.0, 1e-12);
    const Vec3 forward = glm::normalize(cameras[c].target - cameras[c].eye);
    EXPECT_NEAR(glm::distance(glm::normalize(read.target - read.eye), forward), 0.0, 1e-12);
    // The up vector comes back made orthogonal to the view, in the same plane.
    const Vec3 up = glm::normalize(cameras[c].up - glm::dot(cameras[c].up, forward) * forward);
    EXPECT_NEAR(glm::distance(read.up, up), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(read.yfov, cameras[c].yfov);
  }
  const GltfDocument document(path("cameras.glb"));
  for (const tinygltf::Camera& camera : document.model().cameras) {
    EXPECT_GT(camera.perspective.znear, 0.0);
    EXPECT_GT(camera.perspective.zfar, camera.perspective.znear);
  }
  EXPECT_TRUE(loadFile(path("cameras.glb")).scene.polygons.empty());
}

TEST_F(SolutionFileTest, CameraThatMakesNoViewIsRefused) {
  const SceneCamera alongUp{"along up", Vec3(0.0, 0.0, 5.0), Vec3(0.0), Vec3(0.0, 0.0, 1.0), 1.0};
  const SceneCamera noFov{"no fov", Vec3(0.0, 0.0, 5.0), Vec3(0.0), Vec3(0.0, 1.0, 0.0), 0.0};
  for (const SceneCamera& camera : {alongUp, noFov}) {
    SCOPED_TRACE(camera.name);
    try {
      writeSolution(sampleMesh(), path("bad-camera.glb"), {camera});
      FAIL() << "no error";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("bad-camera.glb"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(camera.name), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(path("bad-camera.glb")));
  }
}

// What another glTF viewer sees: triangles that cover every element exactly once, no
// degenerate ones (quadratic elements are not fanned along their straight edges), a tone
// mapped COLOR_0 in [0,1], POSITION bounds, and no required extension.
TEST_F(SolutionFileTest, OtherViewersSeeAPlainTriangleScene) {
  const RadiosityMesh mesh = sampleMesh();
  writeSolution(mesh, path("viewer.glb"));
  const GltfDocument document(path("viewer.glb"));
  std::vector<std::string> warnings;
  const Scene scene = importScene(document, warnings);
  double elementArea = 0.0, triangleArea = 0.0;
  for (size_t e = 0; e < mesh.elements.size(); ++e) elementArea += area(mesh.cornerPositions(e));
  for (const Polygon& p : scene.polygons) {
    triangleArea += area(p.vertices);
    EXPECT_NEAR(glm::distance(unitNormal(p.vertices), Vec3(0, 0, 1)), 0.0, 1e-6);
  }
  EXPECT_EQ(scene.polygons.size(), 4u + 4u + 2u + 6u + 1u);
  EXPECT_NEAR(triangleArea, elementArea, 1e-5);
  for (const std::string& w : warnings) EXPECT_EQ(w.find("degenerate"), std::string::npos) << w;

  const tinygltf::Model& model = document.model();
  EXPECT_TRUE(model.extensionsRequired.empty());
  EXPECT_TRUE(document.usesExtension(kSolutionExtension));
  const double scale = toneMapScale(mesh);
  for (const tinygltf::Primitive& p : model.meshes[0].primitives) {
    EXPECT_EQ(model.accessors[size_t(p.attributes.at("POSITION"))].minValues.size(), 3u);
    EXPECT_EQ(model.accessors[size_t(p.attributes.at("POSITION"))].maxValues.size(), 3u);
    const std::vector<Vec3> color = document.readVec3(p.attributes.at("COLOR_0"), {"COLOR_0", 3, kFloat, false});
    const std::vector<Vec3> B = document.readVec3(p.attributes.at("_RADIOSITY"), {"_RADIOSITY", 3, kFloat, false});
    for (size_t v = 0; v < color.size(); ++v)
      for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(float(color[v][c]), float(std::clamp(B[v][c] * scale, 0.0, 1.0)));
  }
}

TEST_F(SolutionFileTest, ToneMapPutsThe99thPercentileOfNonEmittersAt0_8) {
  RadiosityMesh mesh;
  mesh.materials = {{"grey", Rgb(0.5), Rgb(0.0)}, {"lamp", Rgb(0.5), Rgb(1000.0)}};
  for (int i = 0; i < 102; ++i) {
    Node n;
    n.position = Vec3(i, i % 2, 0);
    n.B = Rgb(i < 100 ? double(i) : 1000.0);
    mesh.nodes.push_back(n);
  }
  for (uint32_t i = 0; i + 2 < 100; ++i) mesh.elements.push_back({{i, i + 1, i + 2}, {}, 0, -1});
  mesh.elements.push_back({{99, 100, 101}, {}, 1, -1});
  // Lit nodes: 0..99 (node 99 borders the lamp too), luminance = i; the 99th percentile of
  // 100 values is element floor(0.99 * 99) = 98 of the sorted list.
  EXPECT_DOUBLE_EQ(toneMapScale(mesh), 0.8 / 98.0);
}

// --- refusals -----------------------------------------------------------------------------

TEST_F(SolutionFileTest, WriteRefusesBadPathsAndInvalidMeshes) {
  const RadiosityMesh mesh = sampleMesh();
  EXPECT_THROW(writeSolution(mesh, path("solution.obj")), Error);
  EXPECT_THROW(writeSolution(mesh, path("no/such/dir/solution.glb")), Error);
  RadiosityMesh broken = mesh;
  broken.elements[0].corners[0] = 99;
  try {
    writeSolution(broken, path("broken.glb"));
    ADD_FAILURE() << "an element referring to node 99 was written";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("element 0 refers to node 99"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(path("broken.glb")));
}

TEST_F(SolutionFileTest, ExtensionAccessorOutOfRange) {
  const std::string file =
      damaged("oob.gltf", [](tinygltf::Model& m) { firstPrimitiveExtension(m)["corners"] = tinygltf::Value(999); });
  const std::string message = readError(file);
  EXPECT_NE(message.find(file), std::string::npos) << message;
  EXPECT_NE(message.find("RADVIEW_radiosity_mesh.corners: accessor 999 does not exist"), std::string::npos) << message;
}

TEST_F(SolutionFileTest, CornerOffsetsNotMonotone) {
  // Primitive 0 holds elements 0, 1, 3, 4: offsets 0 6 9 13 16. Make the third one 5.
  const std::string file = damaged("offsets.gltf", [](tinygltf::Model& m) { setUint(m, "cornerOffsets", 2, 5); });
  const std::string message = readError(file);
  EXPECT_NE(message.find("cornerOffsets: element 1 spans offsets 6 -> 5"), std::string::npos) << message;
}

TEST_F(SolutionFileTest, NodeIndexPastNodeCount) {
  const std::string file = damaged("node.gltf", [](tinygltf::Model& m) { setUint(m, "node", 0, 1000); });
  const std::string message = readError(file);
  EXPECT_NE(message.find("RADVIEW_radiosity_mesh.node: accessor"), std::string::npos) << message;
  EXPECT_NE(message.find("is 1000, out of range (must be < 26)"), std::string::npos) << message;
}

TEST_F(SolutionFileTest, ElementOrderSeven) {
  const std::string file = damaged("order.gltf", [](tinygltf::Model& m) {
    const int accessor = firstPrimitiveExtension(m)["order"].GetNumberAsInt();
    accessorBytes(m, accessor)[0] = 7;
  });
  EXPECT_NE(readError(file).find("element 0 has order 7 (expected 1 or 2)"), std::string::npos);
}

TEST_F(SolutionFileTest, DiscontinuityOrderOutOfRange) {
  const std::string file = damaged("continuity.gltf", [](tinygltf::Model& m) {
    const int accessor = m.extensions[kSolutionExtension].Get("discontinuityOrders").GetNumberAsInt();
    accessorBytes(m, accessor)[1] = 5;
  });
  EXPECT_NE(readError(file).find("edge 1 has order 5 (expected -1, 0 or 1)"), std::string::npos);
}

TEST_F(SolutionFileTest, NodeCountLargerThanTheFileHolds) {
  const std::string file = damaged("count.gltf", [](tinygltf::Model& m) {
    m.extensions[kSolutionExtension].Get<tinygltf::Value::Object>()["nodeCount"] = tinygltf::Value(1000000);
  });
  EXPECT_NE(readError(file).find("nodeCount 1000000 is more than the primitives store"), std::string::npos);
}

// A hostile file: the counts in the extension, mere JSON numbers, declare billions; the data is
// the sample's few hundred bytes. Refused by the limits (core/limits.h) before any allocation.
TEST_F(SolutionFileTest, DeclaredCountsPastTheLimitsAreRefused) {
  for (const char* key : {"nodeCount", "elementCount"}) {
    const std::string file = damaged(std::string(key) + ".gltf", [&](tinygltf::Model& m) {
      m.extensions[kSolutionExtension].Get<tinygltf::Value::Object>()[key] = tinygltf::Value(2000000000);
    });
    const std::string message = readError(file);
    EXPECT_NE(message.find(file + ": 2000000000 "), std::string::npos) << message;
    EXPECT_NE(message.find(std::string("(RADVIEW_radiosity_mesh.") + key + "), more than radview's limit of " +
                           std::to_string(std::string(key) == "nodeCount" ? kMaxSolutionNodes : kMaxSolutionElements)),
              std::string::npos)
        << message;
  }
}

// The writer refuses what the reader would: here an element with more corners than the limit.
TEST_F(SolutionFileTest, WriterRefusesAnElementPastTheCornerLimit) {
  RadiosityMesh mesh;
  mesh.materials = {{"white", Rgb(0.5), Rgb(0.0)}};
  Element disc;
  const int n = int(kMaxElementCorners) + 1;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    mesh.nodes.push_back({Vec3(std::cos(a), std::sin(a), 0.0), Rgb(1.0)});
    disc.corners.push_back(uint32_t(i));
  }
  mesh.elements = {disc};
  const std::string file = path("disc.glb");
  try {
    writeSolution(mesh, file);
    ADD_FAILURE() << "a 1025-corner element was written";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(file + ": 1025 corners in element 0, more than radview's limit of 1024"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(file));
}

TEST_F(SolutionFileTest, ElementStoredTwice) {
  // Primitive 1 holds element 2 only; make it claim element 0, which primitive 0 holds.
  const std::string file = damaged("element.gltf", [](tinygltf::Model& m) {
    const int accessor = m.meshes[0].primitives[1].extensions[kSolutionExtension].Get("element").GetNumberAsInt();
    std::memset(accessorBytes(m, accessor), 0, 4);
  });
  EXPECT_NE(readError(file).find("element 0 is stored a second time"), std::string::npos);
}

TEST_F(SolutionFileTest, NewerFormatVersionIsRefused) {
  const std::string file = damaged("version.gltf", [](tinygltf::Model& m) {
    m.extensions[kSolutionExtension].Get<tinygltf::Value::Object>()["version"] = tinygltf::Value(2);
  });
  EXPECT_NE(readError(file).find("version 2 is not supported"), std::string::npos);
}

TEST_F(SolutionFileTest, NodeStoredTwiceWithDifferentValues) {
  // Node 1 borders both materials; change its radiosity in the second primitive only.
  const std::string file = damaged("twice.gltf", [](tinygltf::Model& m) {
    tinygltf::Primitive& p = m.meshes[0].primitives[1];
    const float B[3] = {1, 2, 3};
    std::memcpy(accessorBytes(m, p.attributes["_RADIOSITY"]), B, sizeof B);  // vertex 0 = node 1
  });
  EXPECT_NE(readError(file).find("node 1 differs from its copy in an earlier primitive"), std::string::npos);
}

TEST_F(SolutionFileTest, StandardErrorsThatAreNegativeMissingOrNotFlaggedAreRefused) {
  const std::string negative = damaged("negative.gltf", [](tinygltf::Model& m) {
    tinygltf::Primitive& p = m.meshes[0].primitives[0];
    const float error[3] = {-1e-3f, 0.0f, 0.0f};
    std::memcpy(accessorBytes(m, p.attributes["_RADIOSITY_STANDARD_ERROR"]), error, sizeof error);
  });
  EXPECT_NE(readError(negative).find("standard error that is negative or not finite"), std::string::npos);
  const std::string missing = damaged("missing.gltf", [](tinygltf::Model& m) {
    m.meshes[0].primitives[0].attributes.erase("_RADIOSITY_STANDARD_ERROR");
  });
  EXPECT_NE(readError(missing).find("has no _RADIOSITY_STANDARD_ERROR attribute"), std::string::npos);
  const std::string notBool = damaged("flag.gltf", [](tinygltf::Model& m) {
    m.extensions[kSolutionExtension].Get<tinygltf::Value::Object>()["hasStandardErrors"] = tinygltf::Value(1);
  });
  EXPECT_NE(readError(notBool).find("hasStandardErrors is not a boolean"), std::string::npos);
}

}  // namespace
}  // namespace radview
