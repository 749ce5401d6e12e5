#include "interp/t_vertex_repair.h"

#include "import/load_file.h"
#include "mesh/topology.h"

#include <gtest/gtest.h>

#include <cmath>

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

TEST(TVertexRepair, ATaggedEdgeThroughTVerticesIsSplitWithThem) {
  RadiosityMesh mesh = loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/t_vertices.gltf").mesh;
  // Tag the coarse quads' right edges (the seam x = 0.5, with the two T-vertices) C0.
  for (const Element& e : mesh.elements)
    for (size_t k = 0; k < e.corners.size(); ++k) {
      const Vec3 p = mesh.nodes[e.corners[k]].position, q = mesh.nodes[e.corners[(k + 1) % e.corners.size()]].position;
      if (p.x == 0.5 && q.x == 0.5 && std::abs(p.y - q.y) == 0.5)
        mesh.discontinuities.push_back({e.corners[k], e.corners[(k + 1) % e.corners.size()], Continuity::C0});
    }
  ASSERT_EQ(mesh.discontinuities.size(), 2u);
  const RadiosityMesh fixed = repairTVertices(mesh);
  EXPECT_EQ(fixed.discontinuities.size(), 4u);
  EXPECT_EQ(MeshTopology(fixed).countEdges(Continuity::C0), 4u);  // throws if a tag were not an edge
}

TEST(TVertexRepair, AMeshWithoutTVerticesIsUnchanged) {
  const RadiosityMesh mesh = loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/fig9_8_quad.gltf").mesh;
  size_t repaired = 1;
  EXPECT_EQ(repairTVertices(mesh, &repaired).elements.size(), mesh.elements.size());
  EXPECT_EQ(repaired, 0u);
}

}  // namespace
}  // namespace radview
