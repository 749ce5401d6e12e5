#include "mesh/display_mesh.h"

#include <gtest/gtest.h>

namespace radview {
namespace {

double triangleArea(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  return 0.5 * glm::length(glm::cross(b - a, c - a));
}

RadiosityMesh withNodes(const std::vector<Vec3>& positions) {
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"m", Rgb(0.5), Rgb(0.0)});
  for (size_t i = 0; i < positions.size(); ++i) mesh.nodes.push_back({positions[i], Rgb(double(i)), {}});
  return mesh;
}

TEST(DisplayMesh, TwoQuadsSharingAnEdgeDrawItOnce) {
  RadiosityMesh mesh = withNodes({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}});
  mesh.elements = {Element{{0, 1, 4, 3}, {}, 0, 0}, Element{{1, 2, 5, 4}, {}, 0, 0}};
  const DisplayMesh display = buildDisplayMesh(mesh, MeshTopology(mesh));
  EXPECT_EQ(displayTriangles(mesh, MeshTopology(mesh)).size(), 12u);  // 2 triangles per quad
  EXPECT_EQ(display.elementEdges.size(), 14u);  // 7 distinct edges, 2 points each
}

TEST(DisplayMesh, QuadraticTriangleIsCutAtItsMidEdgeNodes) {
  RadiosityMesh mesh = withNodes({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  mesh.elements = {Element{{0, 1, 2}, {3, 4, 5}, 0, 0}};
  const DisplayMesh display = buildDisplayMesh(mesh, MeshTopology(mesh));
  const std::vector<DisplayVertex> triangles = displayTriangles(mesh, MeshTopology(mesh));
  ASSERT_EQ(triangles.size(), 12u);
  double total = 0.0;
  for (size_t i = 0; i < triangles.size(); i += 3) {
    const double a = triangleArea(triangles[i].position, triangles[i + 1].position, triangles[i + 2].position);
    EXPECT_NEAR(a, 0.5, 1e-6);
    total += a;
  }
  EXPECT_NEAR(total, 2.0, 1e-6);
  EXPECT_EQ(display.elementEdges.size(), 12u);  // each edge in two halves
  // Every vertex carries its node's value; the flat value is the mean of all six nodes.
  for (const DisplayVertex& v : triangles) EXPECT_FLOAT_EQ(v.Bflat.r, 2.5f);
}

TEST(DisplayMesh, ConcaveElementIsCoveredExactly) {
  // An L-shaped element of area 3.
  RadiosityMesh mesh = withNodes({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}});
  mesh.elements = {Element{{0, 1, 2, 3, 4, 5}, {}, 0, 0}};
  const std::vector<DisplayVertex> triangles = displayTriangles(mesh, MeshTopology(mesh));
  double total = 0.0;
  for (size_t i = 0; i < triangles.size(); i += 3) {
    const glm::vec3 n = glm::cross(triangles[i + 1].position - triangles[i].position,
                                   triangles[i + 2].position - triangles[i].position);
    EXPECT_GT(n.z, 0.0f);  // orientation kept
    total += 0.5 * glm::length(n);
  }
  EXPECT_NEAR(total, 3.0, 1e-6);
}

}  // namespace
}  // namespace radview
