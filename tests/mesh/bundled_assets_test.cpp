// The bundled assets hold what they claim. assets/fig9_8_quad.gltf is written by the
// solution writer from the definition below:
//   RADVIEW_UPDATE_ASSETS=1 build/radview_unit_tests --gtest_filter='BundledAssets.*'
#include "mesh/load_file.h"
#include "mesh/solution_file.h"

#include <gtest/gtest.h>

#include <cstdlib>

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
