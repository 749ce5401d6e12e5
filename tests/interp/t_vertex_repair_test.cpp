#include "interp/t_vertex_repair.h"

#include "mesh/load_file.h"
#include "mesh/topology.h"

#include <gtest/gtest.h>

namespace radview {
namespace {

TEST(TVertexRepair, ElementsWithTVerticesBecomeTrianglesThroughThem) {
  const RadiosityMesh mesh = loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/t_vertices.gltf").mesh;
  ASSERT_EQ(MeshTopology(mesh).tVertices().size(), 2u);
  size_t repaired = 0;
  const RadiosityMesh fixed = repairTVertices(mesh, &repaired);
  EXPECT_EQ(repaired, 2u);  // the two coarse quads, each with one T-vertex on its right edge
  EXPECT_EQ(MeshTopology(fixed).tVertices().size(), 0u);
  // 8 fine quads kept; each coarse quad (5 boundary nodes) becomes 3 triangles.
  EXPECT_EQ(fixed.elements.size(), 8u + 2u * 3u);
  EXPECT_EQ(fixed.nodes.size(), mesh.nodes.size());
}

TEST(TVertexRepair, AMeshWithoutTVerticesIsUnchanged) {
  const RadiosityMesh mesh = loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/fig9_8_quad.gltf").mesh;
  size_t repaired = 1;
  EXPECT_EQ(repairTVertices(mesh, &repaired).elements.size(), mesh.elements.size());
  EXPECT_EQ(repaired, 0u);
}

}  // namespace
}  // namespace radview
