#include "mesh/uniform_mesher.h"

#include "../solve/cornell_box.h"
#include "core/error.h"
#include "geom/polygon.h"
#include "mesh/topology.h"
#include "scene/quad_merge.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace radview {
namespace {

Scene sceneOf(const std::vector<std::vector<Vec3>>& polygons) {
  Scene scene;
  scene.materials.resize(2);
  for (const auto& p : polygons) scene.polygons.push_back({p, 1});
  return scene;
}

double meshArea(const RadiosityMesh& mesh) {
  double sum = 0.0;
  for (size_t e = 0; e < mesh.elements.size(); ++e) sum += area(mesh.cornerPositions(e));
  return sum;
}

TEST(UniformMesherTest, RectangleBecomesAGridOfQuads) {
  const std::vector<Vec3> rect{{0, 0, 0}, {1, 0, 0}, {1, 0.5, 0}, {0, 0.5, 0}};
  const RadiosityMesh mesh = meshUniformly(sceneOf({rect}), 0.2);
  EXPECT_EQ(mesh.elements.size(), 5u * 3u);
  EXPECT_EQ(mesh.nodes.size(), 6u * 4u);
  EXPECT_EQ(mesh.materials.size(), 2u);
  for (size_t e = 0; e < mesh.elements.size(); ++e) {
    EXPECT_EQ(mesh.elements[e].corners.size(), 4u);
    EXPECT_EQ(mesh.elements[e].surface, 0);
    EXPECT_EQ(mesh.elements[e].material, 1);
    EXPECT_NEAR(glm::distance(mesh.elementNormal(e), Vec3(0, 0, 1)), 0.0, 1e-15);
    EXPECT_NEAR(area(mesh.cornerPositions(e)), 0.5 / 15, 1e-15);
  }
  validateMesh(mesh, "uniform mesh");
}

TEST(UniformMesherTest, ConvexQuadIsCutBilinearly) {
  // Trapezoid: opposite edges 2 and 1 along u (n = 4 at size 0.5), both sqrt(1.25) along v (m = 3).
  const std::vector<Vec3> v{{0, 0, 0}, {2, 0, 0}, {1.5, 1, 0}, {0.5, 1, 0}};
  const RadiosityMesh mesh = meshUniformly(sceneOf({v}), 0.5);
  ASSERT_EQ(mesh.elements.size(), 12u);
  ASSERT_EQ(mesh.nodes.size(), 20u);
  // Every node is a bilinear image of a grid point (s, t) = (i/4, j/3), and every one is used.
  int matched = 0;
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 3; ++j) {
      const double s = i / 4.0, t = j / 3.0;
      const Vec3 p = (1 - s) * (1 - t) * v[0] + s * (1 - t) * v[1] + s * t * v[2] + (1 - s) * t * v[3];
      for (const Node& node : mesh.nodes) matched += glm::distance(node.position, p) < 1e-14;
    }
  EXPECT_EQ(matched, 20);
  EXPECT_NEAR(meshArea(mesh), area(v), 1e-14);
}

TEST(UniformMesherTest, TriangleIsSubdividedRegularly) {
  // Longest edge |(1,0) - (0.3,0.8)| = 1.063: n = 5 at size 0.25.
  const std::vector<Vec3> t{{0, 0, 0}, {1, 0, 0}, {0.3, 0.8, 0}};
  const RadiosityMesh mesh = meshUniformly(sceneOf({t}), 0.25);
  ASSERT_EQ(mesh.elements.size(), 25u);
  EXPECT_EQ(mesh.nodes.size(), 21u);  // (n + 1)(n + 2) / 2
  for (size_t e = 0; e < mesh.elements.size(); ++e) {
    EXPECT_EQ(mesh.elements[e].corners.size(), 3u);
    EXPECT_NEAR(area(mesh.cornerPositions(e)), area(t) / 25, 1e-15);
    EXPECT_GT(mesh.elementNormal(e).z, 0.0);
  }
  EXPECT_TRUE(MeshTopology(mesh).tVertices().empty());
}

TEST(UniformMesherTest, ConcavePolygonIsTriangulatedIntoAConformingMesh) {
  const std::vector<Vec3> l{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  const RadiosityMesh mesh = meshUniformly(sceneOf({l}), 0.3);
  EXPECT_NEAR(meshArea(mesh), 3.0, 1e-13);
  const MeshTopology topology(mesh);
  EXPECT_TRUE(topology.tVertices().empty());
  EXPECT_EQ(topology.positionCount(), mesh.nodes.size());  // nodes welded within the polygon
  // Boundary edges (one side) make up exactly the perimeter; all others have two sides.
  for (const MeshEdge& edge : topology.edges()) ASSERT_LE(topology.sides(edge).size(), 2u);
  double boundary = 0.0;
  for (uint32_t e = 0; e < mesh.elements.size(); ++e)
    for (uint32_t i = 0; i < mesh.elements[e].corners.size(); ++i)
      if (topology.neighbour(e, i) < 0) {
        const auto& c = mesh.elements[e].corners;
        boundary += glm::distance(mesh.nodes[c[i]].position, mesh.nodes[c[(i + 1) % c.size()]].position);
      }
  EXPECT_NEAR(boundary, 8.0, 1e-12);
}

TEST(UniformMesherTest, NodesAreNotSharedAcrossPolygons) {
  const RadiosityMesh mesh = meshUniformly(
      sceneOf({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}}}), 0.5);
  EXPECT_EQ(mesh.nodes.size(), 2u * 9u);
  EXPECT_EQ(mesh.elements[7].surface, 1);
  const MeshTopology topology(mesh);
  EXPECT_EQ(topology.positionCount(), 15u);  // but the seam's positions weld
}

TEST(UniformMesherTest, WarpedQuadIsMeshedAsTriangles) {
  const Scene wall = test::cornellBox();
  const RadiosityMesh mesh = meshUniformly(sceneOf({wall.polygons[5].vertices}), 100.0);  // the red wall
  for (const Element& e : mesh.elements) EXPECT_EQ(e.corners.size(), 3u);
  EXPECT_FALSE(mesh.elements.empty());
}

TEST(UniformMesherTest, ZeroAreaPolygonsGetNoElements) {
  const RadiosityMesh mesh = meshUniformly(sceneOf({{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}}), 0.1);
  EXPECT_TRUE(mesh.elements.empty());
}

TEST(UniformMesherTest, BadSizesAndSelfIntersectingPolygonsThrow) {
  const Scene square = sceneOf({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}});
  for (double size : {0.0, -1.0, double(NAN), double(INFINITY)})
    EXPECT_THROW(meshUniformly(square, size), Error) << size;
  const Scene bowtie = sceneOf({{{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0.5, 0}}});
  try {
    meshUniformly(bowtie, 0.1);
    FAIL() << "no Error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("polygon 0: ", 0), 0u) << e.what();
  }
}

TEST(UniformMesherTest, TooManyElementsNamesASizeThatFits) {
  // A 1000 x 1000 square at size 0.5: 4 million elements. Fitting 2 million needs
  // ceil(1000 / s)^2 <= 2e6, s >= 1000 / 1414 = 0.70721..., rounded up to 0.708.
  const Scene square = sceneOf({{{0, 0, 0}, {1000, 0, 0}, {1000, 1000, 0}, {0, 1000, 0}}});
  try {
    meshUniformly(square, 0.5);
    FAIL() << "no Error";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("gives 4000000 elements"), std::string::npos) << message;
    EXPECT_NE(message.find("an element size of 0.708 or more fits"), std::string::npos) << message;
  }
  try {
    meshUniformly(square, 1e-300);  // ceil(1e303)^2 elements: the count must not overflow
    FAIL() << "no Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("an element size of 0.708 or more fits"), std::string::npos) << e.what();
  }
}

TEST(UniformMesherTest, CornellBoxElementCounts) {
  const Scene box = test::cornellBox();
  const double diagonal = box.bounds().diagonal();
  for (double divisor : {20.0, 40.0, 80.0}) {
    const RadiosityMesh mesh = meshUniformly(box, diagonal / divisor);
    std::printf("Cornell box, element size diagonal/%g = %.1f mm: %zu elements, %zu nodes\n", divisor,
                diagonal / divisor, mesh.elements.size(), mesh.nodes.size());
    validateMesh(mesh, "Cornell box");
    // Equal but for the warped red wall, whose triangles have a little more area than its
    // projection on the mean plane.
    double polygonArea = 0.0;
    for (const Polygon& p : box.polygons) polygonArea += area(p.vertices);
    EXPECT_NEAR(meshArea(mesh), polygonArea, 1e-5 * polygonArea);
  }
  const size_t atDefault = meshUniformly(box, diagonal / 40).elements.size();
  EXPECT_GT(atDefault, 2000u);
  EXPECT_LT(atDefault, 6000u);
}

}  // namespace
}  // namespace radview
