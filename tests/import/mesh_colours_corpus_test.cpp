// loadFile over every file of the third-party vertex-colour corpus (shared/corpus/mesh-colours,
// PLY and OBJ from assimp, trimesh, draco, ply-rs, tinyobjloader and a radiosity solver): each
// opens with the nodes and faces its README lists, or is refused with the reason it deserves.
#include "import/load_file.h"

#include "core/error.h"
#include "tests/shared_corpus.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

namespace radview {
namespace {

namespace fs = std::filesystem;

struct Expected {
  size_t nodes = 0, elements = 0, quads = 0;  // when it opens
  std::string refusal;                        // when it is refused: part of the reason
};

// Nodes are the files' vertices (OBJ: its `v` lines, which Assimp's per-corner copies are joined
// back into). Faces of zero area are dropped, with a warning.
const std::map<std::string, Expected> kExpected = {
    {"assimp_float-color.ply", {3, 1, 0, ""}},
    {"assimp_points.ply", {0, 0, 0, "no faces: a point cloud of 4 vertices"}},
    {"assimp_pond.0.ply", {0, 0, 0, "no faces: a point cloud of 70051 vertices"}},
    {"draco_Box.ply", {24, 8, 4, ""}},
    {"draco_test_extra_whitespace.ply", {3, 1, 0, ""}},
    {"draco_test_more_datatypes.ply", {3, 1, 0, ""}},
    {"draco_test_pos_color_ascii.ply", {114, 224, 0, ""}},
    {"draco_test_pos_color_big_endian.ply", {114, 224, 0, ""}},
    {"plyrs_greg_turk_example2_ok_ascii.ply", {8, 7, 5, ""}},
    {"trimesh_fixed_top.ply", {0, 0, 0, "this file's colours are per face"}},
    {"trimesh_fuze.ply", {502, 1000, 0, ""}},
    {"trimesh_fuze_ascii.ply", {0, 0, 0, "face 0 has 21 values where the header's properties take 15"}},
    {"trimesh_multi.ply", {4, 1, 1, ""}},
    {"trimesh_reference.ply", {845, 1610, 0, ""}},
    {"assimp_cube_with_vertexcolors.obj", {8, 12, 0, ""}},
    {"assimp_only_a_part_of_vertexcolors.obj", {5, 3, 0, ""}},
    {"cornellbox_cornell_radiosity.obj", {7119, 13056, 0, ""}},
    {"tinyobj_cube-vertex-w-component.obj", {0, 0, 0, "no vertex colours"}},
    {"tinyobj_cube-vertexcol.obj", {8, 6, 6, ""}},
    {"trimesh_nancolor.obj", {0, 0, 0, "has colour nan nan nan, not finite numbers"}},
    {"trimesh_quadknot.obj", {1440, 1440, 1440, ""}},
    {"trimesh_reference.obj", {845, 1610, 0, ""}},
};

TEST(SharedCorpusMeshColours, EveryFileOpensOrIsRefusedWithItsReason) {
  const fs::path root = RADVIEW_MESH_CORPUS_DIR;
  RADVIEW_REQUIRE_SHARED_CORPUS(root);
  size_t seen = 0;
  for (const auto& entry : fs::directory_iterator(root)) {
    const std::string name = entry.path().filename().string();
    const std::string ext = entry.path().extension().string();
    if (ext != ".ply" && ext != ".obj") continue;
    ++seen;
    const auto expected = kExpected.find(name);
    ASSERT_NE(expected, kExpected.end()) << name << " is new to the corpus: add what it should give";
    try {
      const LoadedFile file = loadFile(entry.path().string());
      EXPECT_TRUE(expected->second.refusal.empty()) << name << " opened, expected: " << expected->second.refusal;
      EXPECT_TRUE(file.isSolution) << name;
      EXPECT_EQ(file.mesh.nodes.size(), expected->second.nodes) << name;
      EXPECT_EQ(file.mesh.elements.size(), expected->second.elements) << name;
      size_t quads = 0;
      for (const Element& e : file.mesh.elements) quads += e.corners.size() == 4;
      EXPECT_EQ(quads, expected->second.quads) << name;
      EXPECT_FALSE(file.valueSource.empty()) << name;
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(entry.path().string() + ": ", 0), 0u) << message;
      EXPECT_FALSE(expected->second.refusal.empty()) << name << " refused: " << message;
      if (!expected->second.refusal.empty()) {
        EXPECT_NE(message.find(expected->second.refusal), std::string::npos) << name << ": " << message;
      }
    }
  }
  EXPECT_EQ(seen, kExpected.size());
}

// The solver's output holds 104 vertices at exactly 1 1 1 (the light): as floats they are
// linear radiosity 1, the brightest nodes of the mesh.
TEST(SharedCorpusMeshColours, RadiositySolverOutputKeepsItsValues) {
  const fs::path file = fs::path(RADVIEW_MESH_CORPUS_DIR) / "cornellbox_cornell_radiosity.obj";
  RADVIEW_REQUIRE_SHARED_CORPUS(file);
  const LoadedFile loaded = loadFile(file.string());
  size_t white = 0;
  double brightest = 0.0;
  for (const Node& n : loaded.mesh.nodes) {
    white += n.B == Rgb(1.0);
    brightest = std::max({brightest, n.B.r, n.B.g, n.B.b});
  }
  EXPECT_EQ(white, 104u);
  EXPECT_EQ(brightest, 1.0);
}

}  // namespace
}  // namespace radview
