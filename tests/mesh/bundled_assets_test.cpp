// The bundled assets hold what they claim. assets/fig9_8_quad.gltf and
// assets/discontinuities.gltf are written by the solution writer from the definitions below:
//   RADVIEW_UPDATE_ASSETS=1 build/radview_unit_tests --gtest_filter='BundledAssets.*'
#include "import/load_file.h"
#include "mesh/solution_file.h"
#include "mesh/topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>

namespace radview {
namespace {

const std::string assets = std::string(RADVIEW_SOURCE_DIR) + "/assets/";

// C&W fig. 9.8: one quad with four distinct vertex radiosities. The diagonals differ as much
// as possible (0.9 and 0.7 against 0.1 and 0.3), so the value at the centre is 0.8 or 0.2
// depending on which diagonal a scanline or triangle split follows, and 0.5 bilinearly.
RadiosityMesh fig98Quad() {
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"grey", Rgb(0.5), Rgb(0.0)});
  const double B[4] = {0.9, 0.1, 0.7, 0.3};
  const Vec3 corners[4] = {{-0.5, -0.5, 0.0}, {0.5, -0.5, 0.0}, {0.5, 0.5, 0.0}, {-0.5, 0.5, 0.0}};
  for (int i = 0; i < 4; ++i) mesh.nodes.push_back({corners[i], Rgb(B[i]), {}});
  mesh.elements.push_back(Element{{0, 1, 2, 3}, {}, 0, 0});
  return mesh;
}

// A unit square (z = 0, facing +z) whose radiosity has the two kinds of discontinuity of
// Salesin et al. 1992, on mesh lines tagged accordingly:
//   B(x, y) = 0.5 + 0.2 sin(3x) cos(2y) + 0.8 max(0, x - 0.5) - 0.3 [y < 0.3]
// a kink (C0) along x = 0.5 and a step (C-1) of 0.3 along y = 0.3, where each node carries
// two values, one per side (two nodes at one position).
double demoB(double x, double y, bool below) {
  return 0.5 + 0.2 * std::sin(3 * x) * std::cos(2 * y) + 0.8 * std::max(0.0, x - 0.5) - (below ? 0.3 : 0.0);
}

RadiosityMesh discontinuityDemo() {
  const std::vector<double> xs = {0, 0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1};
  const std::vector<double> ys = {0, 0.15, 0.3, 0.475, 0.65, 0.825, 1};
  const size_t stepRow = 2;  // ys[2] = 0.3
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"grey", Rgb(0.5), Rgb(0.0)});
  // node[row][column][side]: side 1 is the copy above the step line (the same node elsewhere).
  std::vector<std::vector<std::array<uint32_t, 2>>> node(ys.size(), std::vector<std::array<uint32_t, 2>>(xs.size()));
  for (size_t j = 0; j < ys.size(); ++j)
    for (size_t i = 0; i < xs.size(); ++i) {
      const bool below = j < stepRow || j == stepRow;
      node[j][i][0] = uint32_t(mesh.nodes.size());
      mesh.nodes.push_back({Vec3(xs[i], ys[j], 0), Rgb(demoB(xs[i], ys[j], below)), {}});
      node[j][i][1] = node[j][i][0];
      if (j == stepRow) {
        node[j][i][1] = uint32_t(mesh.nodes.size());
        mesh.nodes.push_back({Vec3(xs[i], ys[j], 0), Rgb(demoB(xs[i], ys[j], false)), {}});
      }
    }
  for (size_t j = 0; j + 1 < ys.size(); ++j)
    for (size_t i = 0; i + 1 < xs.size(); ++i) {
      // The cell's corners, taking the copies on the cell's side of the step line.
      const uint32_t a = node[j][i][1], b = node[j][i + 1][1], c = node[j + 1][i + 1][0], d = node[j + 1][i][0];
      if ((i + j) % 2) {
        mesh.elements.push_back(Element{{a, b, c}, {}, 0, 0});
        mesh.elements.push_back(Element{{a, c, d}, {}, 0, 0});
      } else {
        mesh.elements.push_back(Element{{a, b, d}, {}, 0, 0});
        mesh.elements.push_back(Element{{b, c, d}, {}, 0, 0});
      }
    }
  const size_t kinkColumn = 4;  // xs[4] = 0.5
  for (size_t j = 0; j + 1 < ys.size(); ++j)
    mesh.discontinuities.push_back({node[j][kinkColumn][1], node[j + 1][kinkColumn][0], Continuity::C0});
  for (size_t i = 0; i + 1 < xs.size(); ++i)
    mesh.discontinuities.push_back({node[stepRow][i][0], node[stepRow][i + 1][0], Continuity::Cm1});
  return mesh;
}

TEST(BundledAssets, DiscontinuityDemoHoldsItsDefinition) {
  const std::string path = assets + "discontinuities.gltf";
  if (std::getenv("RADVIEW_UPDATE_ASSETS")) writeSolution(discontinuityDemo(), path);
  const LoadedFile file = loadFile(path);
  ASSERT_TRUE(file.isSolution);
  const RadiosityMesh want = discontinuityDemo();
  ASSERT_EQ(file.mesh.nodes.size(), want.nodes.size());
  for (size_t i = 0; i < want.nodes.size(); ++i)
    EXPECT_NEAR(glm::length(file.mesh.nodes[i].B - want.nodes[i].B), 0.0, 1e-7) << i;
  EXPECT_EQ(file.mesh.elements.size(), 96u);
  const MeshTopology topology(file.mesh);
  EXPECT_EQ(topology.countEdges(Continuity::C0), 6u);
  EXPECT_EQ(topology.countEdges(Continuity::Cm1), 8u);
  EXPECT_TRUE(topology.tVertices().empty());
}

// Adaptive subdivision's leftover (C&W §9.2): a unit square, 2 x 2 quads on the left half and
// 4 x 4 on the right, so the right half's nodes on x = 0.5 are T-vertices of the left quads.
// B = 0.3 + 0.6 exp(-20 ((x - 0.5)^2 + (y - 0.4)^2)), a highlight on the seam, so the values
// at the T-vertices differ from what the coarse side's edges interpolate there.
RadiosityMesh tVertexDemo() {
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"grey", Rgb(0.5), Rgb(0.0)});
  std::map<std::pair<int, int>, uint32_t> node;  // position in 1/8 units -> node
  auto at = [&](int i, int j) {
    auto it = node.find({i, j});
    if (it != node.end()) return it->second;
    const double x = i / 8.0, y = j / 8.0;
    const double B = 0.3 + 0.6 * std::exp(-20.0 * ((x - 0.5) * (x - 0.5) + (y - 0.4) * (y - 0.4)));
    mesh.nodes.push_back({Vec3(x, y, 0), Rgb(B, B, B), {}});
    return node[{i, j}] = uint32_t(mesh.nodes.size() - 1);
  };
  auto quad = [&](int i, int j, int size) {
    mesh.elements.push_back(Element{{at(i, j), at(i + size, j), at(i + size, j + size), at(i, j + size)}, {}, 0, 0});
  };
  for (int j = 0; j < 8; j += 4)
    for (int i = 0; i < 4; i += 4) quad(i, j, 4);
  for (int j = 0; j < 8; j += 2)
    for (int i = 4; i < 8; i += 2) quad(i, j, 2);
  return mesh;
}

TEST(BundledAssets, TVertexDemoHoldsItsDefinition) {
  const std::string path = assets + "t_vertices.gltf";
  if (std::getenv("RADVIEW_UPDATE_ASSETS")) writeSolution(tVertexDemo(), path);
  const LoadedFile file = loadFile(path);
  ASSERT_TRUE(file.isSolution);
  EXPECT_EQ(file.mesh.nodes.size(), tVertexDemo().nodes.size());
  EXPECT_EQ(file.mesh.elements.size(), 10u);
  // (0.5, 0.25) and (0.5, 0.75) lie inside the left quads' right edges.
  EXPECT_EQ(MeshTopology(file.mesh).tVertices().size(), 2u);
}

TEST(BundledAssets, Fig98QuadHoldsItsDefinition) {
  const std::string path = assets + "fig9_8_quad.gltf";
  if (std::getenv("RADVIEW_UPDATE_ASSETS")) writeSolution(fig98Quad(), path);
  const LoadedFile file = loadFile(path);
  ASSERT_TRUE(file.isSolution);
  const RadiosityMesh want = fig98Quad();
  ASSERT_EQ(file.mesh.nodes.size(), want.nodes.size());
  for (size_t i = 0; i < want.nodes.size(); ++i) {
    EXPECT_EQ(file.mesh.nodes[i].position, want.nodes[i].position);
    EXPECT_NEAR(glm::length(file.mesh.nodes[i].B - want.nodes[i].B), 0.0, 1e-7);
  }
  ASSERT_EQ(file.mesh.elements.size(), 1u);
  EXPECT_EQ(file.mesh.elements[0].corners, want.elements[0].corners);
}

TEST(BundledAssets, CornellBoxIsTheMeasuredScene) {
  const LoadedFile file = loadFile(assets + "cornell_box.gltf");
  ASSERT_FALSE(file.isSolution);
  // 16 measured quads; the red wall is not planar (3 mm) and stays two triangles.
  size_t quads = 0, triangles = 0;
  for (const Polygon& p : file.scene.polygons) (p.vertices.size() == 4 ? quads : triangles)++;
  EXPECT_EQ(quads, 15u);
  EXPECT_EQ(triangles, 2u);
  ASSERT_EQ(file.scene.emitters().size(), 1u);
  const Polygon& light = file.scene.polygons[file.scene.emitters()[0]];
  for (const Vec3& v : light.vertices) EXPECT_NEAR(v.y, 0.5487, 1e-6);  // lowered 0.1 mm
  ASSERT_EQ(file.scene.cameras.size(), 1u);
  EXPECT_NEAR(file.scene.cameras[0].eye.z, -0.8, 1e-6);
  EXPECT_GT(file.scene.cameras[0].target.z, file.scene.cameras[0].eye.z);  // looking into the box
}

}  // namespace
}  // namespace radview
