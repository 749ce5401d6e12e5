#include "mesh/topology.h"

#include "core/error.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <chrono>

namespace radview {
namespace {

// Builds meshes by hand: nodes by position, elements by node lists.
struct MeshBuilder {
  RadiosityMesh mesh;
  MeshBuilder() { mesh.materials.resize(1); }
  uint32_t node(const Vec3& p) {
    Node n;
    n.position = p;
    mesh.nodes.push_back(n);
    return uint32_t(mesh.nodes.size() - 1);
  }
  uint32_t element(std::vector<uint32_t> corners, std::vector<uint32_t> midEdge = {}) {
    Element e;
    e.corners = std::move(corners);
    e.midEdge = std::move(midEdge);
    mesh.elements.push_back(e);
    return uint32_t(mesh.elements.size() - 1);
  }
  // A column of quads [x0, x1] x [y_k, y_k+1] in the plane z = 0 sharing their nodes.
  std::vector<uint32_t> column(double x0, double x1, const std::vector<double>& ys) {
    std::vector<uint32_t> left, right, elements;
    for (double y : ys) {
      left.push_back(node({x0, y, 0}));
      right.push_back(node({x1, y, 0}));
    }
    for (size_t k = 0; k + 1 < ys.size(); ++k)
      elements.push_back(element({left[k], right[k], right[k + 1], left[k + 1]}));
    return elements;
  }
};

TEST(TopologyTest, TwoQuadsSplitDifferentlyHaveExactlyTheExpectedTVertices) {
  // Left column split at y = 1/2, right column at 1/3 and 2/3: each inner node of one side lies
  // inside an edge of the other.
  MeshBuilder b;
  const auto left = b.column(0, 1, {0, 0.5, 1});
  const auto right = b.column(1, 2, {0, 1.0 / 3, 2.0 / 3, 1});
  validateMesh(b.mesh, "test");
  const MeshTopology topology(b.mesh);
  const auto& tv = topology.tVertices();
  ASSERT_EQ(tv.size(), 3u);
  auto expectT = [&](const TVertex& t, const Vec3& at, uint32_t element, uint32_t edge, double param) {
    EXPECT_EQ(b.mesh.nodes[t.node].position, at);
    EXPECT_EQ(t.element, element);
    EXPECT_EQ(t.edge, edge);
    EXPECT_NEAR(t.t, param, 1e-12);
  };
  // Sorted by element: the left quads' right edges (edge 1, running up), then the right middle
  // quad's left edge (edge 3, running down from 2/3 to 1/3).
  expectT(tv[0], {1, 1.0 / 3, 0}, left[0], 1, 2.0 / 3);
  expectT(tv[1], {1, 2.0 / 3, 0}, left[1], 1, 1.0 / 3);
  expectT(tv[2], {1, 0.5, 0}, right[1], 3, 0.5);
  // No edge is shared across x = 1, so no element has a neighbour there.
  EXPECT_EQ(topology.neighbour(left[0], 1), -1);
  EXPECT_EQ(topology.neighbour(left[0], 2), int64_t(left[1]));
}

TEST(TopologyTest, FloorNodeOnTheBottomEdgeOfAPerpendicularWallIsNoTVertex) {
  MeshBuilder b;
  // Floor z = 0, [0,2] x [0,1], split in two at x = 1; back wall y = 1, one quad, facing -y.
  const uint32_t f0 = b.node({0, 0, 0}), f1 = b.node({1, 0, 0}), f2 = b.node({2, 0, 0});
  const uint32_t f3 = b.node({0, 1, 0}), f4 = b.node({1, 1, 0}), f5 = b.node({2, 1, 0});
  b.element({f0, f1, f4, f3});
  b.element({f1, f2, f5, f4});
  const uint32_t w0 = b.node({0, 1, 0}), w1 = b.node({0, 1, 1}), w2 = b.node({2, 1, 1}), w3 = b.node({2, 1, 0});
  b.element({w0, w3, w2, w1});
  ASSERT_GT(glm::dot(b.mesh.elementNormal(2), Vec3(0, -1, 0)), 0.99);
  const MeshTopology topology(b.mesh);
  EXPECT_TRUE(topology.tVertices().empty());
  // The floor's back edges and the wall's bottom edge are separate edges (different end
  // positions): the wall's bottom edge spans both.
  EXPECT_EQ(topology.neighbour(0, 2), -1);
  EXPECT_EQ(topology.neighbour(2, 0), -1);
}

TEST(TopologyTest, BackToBackFacesAreNotOneSurface) {
  MeshBuilder b;
  b.column(0, 1, {0, 0.5, 1});  // faces +z
  const uint32_t a = b.node({0, 0, 0}), c = b.node({1, 1, 0});
  b.element({a, b.node({0, 1, 0}), c, b.node({1, 0, 0})});  // the same square, facing -z
  EXPECT_TRUE(MeshTopology(b.mesh).tVertices().empty());
}

TEST(TopologyTest, DuplicatedNodesAcrossACm1EdgeAreStillNeighbours) {
  MeshBuilder b;
  // Two unit quads meeting at x = 1, each with its own nodes there.
  const uint32_t a0 = b.node({0, 0, 0}), a1 = b.node({1, 0, 0}), a2 = b.node({1, 1, 0}), a3 = b.node({0, 1, 0});
  const uint32_t b0 = b.node({1, 0, 0}), b1 = b.node({2, 0, 0}), b2 = b.node({2, 1, 0}), b3 = b.node({1, 1, 0});
  b.element({a0, a1, a2, a3});
  b.element({b0, b1, b2, b3});
  b.mesh.discontinuities.push_back({a1, a2, Continuity::Cm1});
  b.mesh.discontinuities.push_back({b3, b0, Continuity::C0});  // same edge from the other side
  validateMesh(b.mesh, "test");
  const MeshTopology topology(b.mesh);
  EXPECT_EQ(topology.positionCount(), 6u);
  EXPECT_EQ(topology.positionId(a1), topology.positionId(b0));
  EXPECT_EQ(topology.edges().size(), 7u);
  EXPECT_EQ(topology.neighbour(0, 1), 1);
  EXPECT_EQ(topology.neighbour(1, 3), 0);
  EXPECT_EQ(topology.edgeIndex(0, 1), topology.edgeIndex(1, 3));
  EXPECT_EQ(topology.sides(topology.edges()[topology.edgeIndex(0, 1)]).size(), 2u);
  // Tagged C-1 and C0: the weaker wins.
  EXPECT_EQ(topology.edges()[topology.edgeIndex(0, 1)].continuity, Continuity::Cm1);
  EXPECT_EQ(topology.countEdges(Continuity::Cm1), 1u);
  EXPECT_EQ(topology.countEdges(Continuity::C0), 0u);
  EXPECT_EQ(topology.countEdges(Continuity::C1), 6u);
  EXPECT_TRUE(topology.tVertices().empty());
  for (uint32_t edge : {0u, 2u, 3u}) EXPECT_EQ(topology.neighbour(0, edge), -1);
}

// Every element edge is listed once among its edge's sides, and the edges come ordered by
// their position ids, as the header says.
TEST(TopologyTest, EdgesAreOrderedAndEachElementEdgeIsOneOfItsSides) {
  MeshBuilder b;
  b.column(0, 1, {0, 0.5, 1});
  b.column(1, 2, {0, 1.0 / 3, 2.0 / 3, 1});
  b.column(2, 3, {0, 1});
  const MeshTopology topology(b.mesh);
  for (size_t i = 1; i < topology.edges().size(); ++i) {
    const MeshEdge &p = topology.edges()[i - 1], &q = topology.edges()[i];
    EXPECT_TRUE(p.a < q.a || (p.a == q.a && p.b < q.b)) << "edges " << i - 1 << " and " << i;
  }
  size_t sides = 0;
  for (const MeshEdge& edge : topology.edges()) sides += topology.sides(edge).size();
  size_t corners = 0;
  for (uint32_t e = 0; e < b.mesh.elements.size(); ++e)
    for (uint32_t i = 0; i < b.mesh.elements[e].corners.size(); ++i, ++corners) {
      const MeshEdge& edge = topology.edges()[topology.edgeIndex(e, i)];
      int found = 0;
      for (const EdgeSide& side : topology.sides(edge)) found += side.element == e && side.edge == i;
      EXPECT_EQ(found, 1) << "element " << e << " edge " << i;
    }
  EXPECT_EQ(sides, corners);
}

TEST(TopologyTest, DiscontinuityThatIsNoElementEdgeThrows) {
  MeshBuilder b;
  b.column(0, 1, {0, 1});
  b.mesh.discontinuities.push_back({0, 3, Continuity::C0});  // the quad's diagonal
  try {
    MeshTopology topology(b.mesh);
    FAIL() << "no Error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "discontinuity edge 0 (nodes 0-3) is not an element edge");
  }
}

// checkDiscontinuityEdges agrees with MeshTopology: a tag on an element's own corners, or on
// nodes of two elements that share the edge only by position (a C-1 edge's duplicated nodes),
// passes; the diagonal throws the same message.
TEST(TopologyTest, CheckingTheTagsAloneAgreesWithTheTopology) {
  MeshBuilder b;
  b.column(0, 1, {0, 1});
  b.mesh.discontinuities.push_back({3, 1, Continuity::C0});  // the quad's edge x = 1
  EXPECT_NO_THROW(checkDiscontinuityEdges(b.mesh));
  // A second quad right of it with its own nodes on that edge, tagged across: node 1 of the
  // first and the copy of node 3 in the second.
  const uint32_t copy1 = b.node(b.mesh.nodes[1].position), copy3 = b.node(b.mesh.nodes[3].position);
  b.element({copy1, b.node({2, 0, 0}), b.node({2, 1, 0}), copy3});
  b.mesh.discontinuities.push_back({1, copy3, Continuity::Cm1});
  EXPECT_NO_THROW(MeshTopology{b.mesh});
  EXPECT_NO_THROW(checkDiscontinuityEdges(b.mesh));
  b.mesh.discontinuities.push_back({0, 3, Continuity::C0});  // the first quad's diagonal
  try {
    checkDiscontinuityEdges(b.mesh);
    FAIL() << "no Error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "discontinuity edge 2 (nodes 0-3) is not an element edge");
  }
}

TEST(TopologyTest, WeldsWithinTheToleranceOnly) {
  MeshBuilder b;
  b.column(0, 1, {0, 1});
  const uint32_t near = b.node({1 + 1e-9, 0, 0}), far = b.node({1 + 1e-5, 1, 0});
  b.element({near, b.node({2, 0, 0}), b.node({2, 1, 0}), far});
  const MeshTopology topology(b.mesh);
  EXPECT_EQ(topology.positionId(near), topology.positionId(1));  // node 1 is (1, 0, 0)
  EXPECT_NE(topology.positionId(far), topology.positionId(3));   // node 3 is (1, 1, 0)
  EXPECT_EQ(topology.positionCount(), 7u);
}

TEST(TopologyTest, NonManifoldEdgeHasNoNeighbour) {
  MeshBuilder b;
  const uint32_t p = b.node({0, 0, 0}), q = b.node({1, 0, 0});
  b.element({p, q, b.node({0.5, 1, 0})});
  b.element({q, p, b.node({0.5, -1, 0})});
  b.element({q, p, b.node({0.5, 0, 1})});
  const MeshTopology topology(b.mesh);
  EXPECT_EQ(topology.sides(topology.edges()[topology.edgeIndex(0, 0)]).size(), 3u);
  EXPECT_EQ(topology.neighbour(0, 0), -1);
}

TEST(TopologyTest, SharedMidEdgeNodesOfQuadraticElementsAreNoTVertices) {
  MeshBuilder b;
  const uint32_t p = b.node({0, 0, 0}), q = b.node({1, 0, 0}), r = b.node({0.5, 1, 0}), s = b.node({0.5, -1, 0});
  const uint32_t pq = b.node({0.5, 0, 0});
  b.element({p, q, r}, {pq, b.node({0.75, 0.5, 0}), b.node({0.25, 0.5, 0})});
  b.element({q, p, s}, {pq, b.node({0.25, -0.5, 0}), b.node({0.75, -0.5, 0})});
  validateMesh(b.mesh, "test");
  const MeshTopology topology(b.mesh);
  EXPECT_TRUE(topology.tVertices().empty());
  EXPECT_EQ(topology.neighbour(0, 0), 1);
}

// 150,000 quads in a tilted plane: a 250 x 200 grid beside a 250 x 400 one. The finer side's
// odd nodes on the seam are the only T-vertices.
TEST(TopologyTest, LargeMeshIsFastAndExact) {
  const int nx = 250, ny = 200;
  const glm::dmat4 place = glm::translate(glm::dmat4(1.0), Vec3(12, -3, 40)) *
                           glm::rotate(glm::dmat4(1.0), 0.9, glm::normalize(Vec3(1, -2, 0.5)));
  MeshBuilder b;
  auto grid = [&](double x0, int columns, int rows) {
    const uint32_t first = uint32_t(b.mesh.nodes.size());
    for (int i = 0; i <= columns; ++i)
      for (int j = 0; j <= rows; ++j) b.node(Vec3(place * glm::dvec4(x0 + double(i) / nx, double(j) / rows, 0, 1)));
    auto at = [&](int i, int j) { return first + uint32_t(i * (rows + 1) + j); };
    for (int i = 0; i < columns; ++i)
      for (int j = 0; j < rows; ++j) b.element({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  };
  grid(0.0, nx, ny);
  grid(1.0, nx, 2 * ny);
  ASSERT_EQ(b.mesh.elements.size(), 150000u);
  const auto start = std::chrono::steady_clock::now();
  const MeshTopology topology(b.mesh);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("MeshTopology of %zu elements: %.3f s\n", b.mesh.elements.size(), seconds);
  EXPECT_EQ(topology.tVertices().size(), size_t(ny));
  for (const TVertex& t : topology.tVertices()) {
    EXPECT_LT(t.element, uint32_t(nx * ny));  // on an edge of the coarse side
    EXPECT_NEAR(t.t, 0.5, 1e-9);
  }
  EXPECT_LT(seconds, 20.0);  // a generous bound for a loaded machine; all pairs would take hours
}

}  // namespace
}  // namespace radview
