// Adaptive subdivision: which elements split, the T-vertices it leaves, discontinuity tags
// carried through splits, quadratic elements, and the solution file round trip.
#include "solve/adaptive_subdivision.h"

#include "import/load_file.h"
#include "interp/t_vertex_repair.h"
#include "mesh/solution_file.h"
#include "mesh/topology.h"
#include "mesh/uniform_mesher.h"
#include "solve/radiosity_solve.h"
#include "tests/solve/solver_scenes.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <set>

namespace radview {
namespace {

// Two unit quads side by side on z = 0, facing +z: x in [0, 1] and [1, 2].
RadiosityMesh twoQuads(bool duplicateSharedEdge) {
  RadiosityMesh mesh;
  mesh.materials = {{"grey", Rgb(0.5), Rgb(0.0)}, {"light", Rgb(0.5), Rgb(1.0)}};
  for (Vec3 p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(2, 0, 0), Vec3(2, 1, 0)})
    mesh.nodes.push_back(Node{p});
  mesh.elements.push_back({{0, 1, 2, 3}, {}, 0, 0});
  if (duplicateSharedEdge) {
    mesh.nodes.push_back(Node{Vec3(1, 0, 0)});  // 6, a copy of 1
    mesh.nodes.push_back(Node{Vec3(1, 1, 0)});  // 7, a copy of 2
    mesh.elements.push_back({{6, 4, 5, 7}, {}, 0, 0});
  } else {
    mesh.elements.push_back({{1, 4, 5, 2}, {}, 0, 0});
  }
  return mesh;
}

// Solves the Cornell box with subdivision (patches of 100 mm, to 5 % unshot).
RadiosityMesh solvedCornell(bool quadratic, SolveSummary& summary, bool balance = false, size_t maxElements = 3000) {
  SolveSettings settings;
  settings.subdivision.balance = balance;
  settings.solver.stopUnshotFraction = 0.05;
  settings.solver.quadratic = quadratic;
  settings.subdivision.tolerance = 8.0;
  settings.subdivision.minElementSize = 12.0;
  settings.subdivision.maxElements = maxElements;
  settings.patchSize = 100.0;
  return solveRadiosity(test::cornellBox(), settings, summary);
}

TEST(AdaptiveSubdivisionTest, DisplayValueIsEightBitSrgbOfToneMappedLuminance) {
  EXPECT_DOUBLE_EQ(displayValue(Rgb(0.0), 1.0), 0.0);
  EXPECT_NEAR(displayValue(Rgb(1.0), 1.0), 255.0, 1e-9);
  EXPECT_NEAR(displayValue(Rgb(0.5), 0.4), 255.0 * (1.055 * std::pow(0.2, 1 / 2.4) - 0.055), 1e-9);
  EXPECT_NEAR(displayValue(Rgb(100.0), 1.0), 255.0, 1e-9);  // saturates
}

TEST(AdaptiveSubdivisionTest, ChoosesLargeSpreadsWithinTheLimits) {
  RadiosityMesh mesh = twoQuads(false);
  mesh.nodes[0].B = Rgb(1.0);  // the left quad spans black to white; the right one is flat
  SubdivisionCriteria criteria;
  EXPECT_EQ(elementsToSplit(mesh, criteria), std::vector<uint32_t>{0});
  criteria.minElementSize = 0.6;  // children would be 0.5: too small
  EXPECT_TRUE(elementsToSplit(mesh, criteria).empty());
  criteria.minElementSize = 0.0;
  criteria.maxElements = 4;  // 2 + 3 would be 5
  EXPECT_TRUE(elementsToSplit(mesh, criteria).empty());
  criteria.maxElements = 5;
  mesh.elements[0].material = 1;  // emitters are not split
  EXPECT_TRUE(elementsToSplit(mesh, criteria).empty());
}

// One wide quad below quads that meet on its top edge: at x = 2/3 with their own nodes each (a
// C-1 edge between them: two nodes, one position) the edge holds one T-vertex position and is
// balanced; with a third quad meeting at x = 4/3 too it holds two, and the wide quad is split.
TEST(AdaptiveSubdivisionTest, BalanceCountsTVertexPositionsNotNodes) {
  auto mesh = [](bool third) {
    RadiosityMesh m;
    m.materials = {{"grey", Rgb(0.5), Rgb(0.0)}};
    auto node = [&](double x, double y) {
      m.nodes.push_back(Node{Vec3(x, y, 0)});
      return uint32_t(m.nodes.size() - 1);
    };
    const uint32_t a = node(0, 0), b = node(2, 0), c = node(2, 1), d = node(0, 1);
    m.elements.push_back({{a, b, c, d}, {}, 0, 0});
    const double split = 2.0 / 3.0;
    const uint32_t p = node(split, 1), q = node(split, 2), e = node(0, 2);
    m.elements.push_back({{d, p, q, e}, {}, 0, 0});
    const uint32_t p2 = node(split, 1), q2 = node(split, 2);  // the C-1 edge's other side
    if (third) {
      const uint32_t r = node(2 * split, 1), t = node(2 * split, 2), f = node(2, 2);
      m.elements.push_back({{p2, r, t, q2}, {}, 0, 0});
      m.elements.push_back({{r, c, f, t}, {}, 0, 0});
    } else {
      const uint32_t f = node(2, 2);
      m.elements.push_back({{p2, c, f, q2}, {}, 0, 0});
    }
    validateMesh(m, "balance test");
    return m;
  };
  SubdivisionCriteria criteria;
  EXPECT_TRUE(unbalancedElements(mesh(false), criteria).empty());
  EXPECT_EQ(unbalancedElements(mesh(true), criteria), (std::vector<uint32_t>{0}));
  criteria.minElementSize = 1.5;  // the wide quad's longest edge is 2: below twice that
  EXPECT_TRUE(unbalancedElements(mesh(true), criteria).empty());
}

TEST(AdaptiveSubdivisionTest, SplittingOneSideLeavesATVertexUntilTheOtherSplits) {
  RadiosityMesh mesh = twoQuads(false);
  MeshRefiner refiner(mesh);
  std::vector<uint32_t> parentOf;
  EXPECT_EQ(refiner.split(mesh, {0}, parentOf), 1u);
  EXPECT_EQ(mesh.elements.size(), 5u);
  EXPECT_EQ(parentOf, std::vector<uint32_t>(3, 0));
  validateMesh(mesh, "split once");
  {
    const MeshTopology topology(mesh);
    ASSERT_EQ(topology.tVertices().size(), 1u);  // the middle of the shared edge, on quad 1
    const TVertex& t = topology.tVertices()[0];
    EXPECT_EQ(t.element, 1u);
    EXPECT_EQ(mesh.nodes[t.node].position, Vec3(1, 0.5, 0));
    EXPECT_NEAR(t.t, 0.5, 1e-12);
  }
  // Splitting the neighbour reuses that node: no T-vertex is left, no node doubled.
  const size_t nodes = mesh.nodes.size();
  refiner.split(mesh, {1}, parentOf);
  validateMesh(mesh, "split twice");
  EXPECT_EQ(MeshTopology(mesh).tVertices().size(), 0u);
  EXPECT_EQ(mesh.nodes.size(), nodes + 4);  // 3 edge midpoints and a centre: the shared one reused
}

TEST(AdaptiveSubdivisionTest, DiscontinuityEdgesSurviveSplits) {
  // A C-1 edge (duplicated nodes) between the quads, tagged by the left side's nodes only.
  RadiosityMesh mesh = twoQuads(true);
  mesh.discontinuities = {{1, 2, Continuity::Cm1}};
  MeshRefiner refiner(mesh);
  std::vector<uint32_t> parentOf;
  refiner.split(mesh, {1}, parentOf);  // the right side, whose nodes the tag does not name
  validateMesh(mesh, "right split");
  {
    const MeshTopology topology(mesh);                    // throws if a tag is not an element edge
    EXPECT_EQ(topology.countEdges(Continuity::Cm1), 3u);  // left's whole edge, right's two halves
  }
  refiner.split(mesh, {0}, parentOf);
  validateMesh(mesh, "both split");
  const MeshTopology topology(mesh);
  EXPECT_EQ(topology.countEdges(Continuity::Cm1), 2u);  // the two halves, each with two sides
  for (const MeshEdge& edge : topology.edges()) {
    if (edge.continuity != Continuity::Cm1) continue;
    EXPECT_EQ(topology.sides(edge).size(), 2u);
  }
  // The sides keep their own nodes: the halves' middles are two nodes at one position.
  std::set<uint32_t> middles;
  for (uint32_t i = 0; i < mesh.nodes.size(); ++i)
    if (mesh.nodes[i].position == Vec3(1, 0.5, 0)) middles.insert(i);
  EXPECT_EQ(middles.size(), 2u);

  // A C0 edge (shared nodes), split on one side only: the unsplit side keeps the whole edge
  // tagged, the split side its halves.
  RadiosityMesh shared = twoQuads(false);
  shared.discontinuities = {{2, 1, Continuity::C0}};
  MeshRefiner sharedRefiner(shared);
  sharedRefiner.split(shared, {0}, parentOf);
  EXPECT_EQ(MeshTopology(shared).countEdges(Continuity::C0), 3u);
}

TEST(AdaptiveSubdivisionTest, CornellSolveLeavesTVerticesAndWritesThemBack) {
  SolveSummary summary;
  const RadiosityMesh mesh = solvedCornell(false, summary);
  std::printf("Cornell, patches of 100 mm: %zu patches -> %zu elements in %d rounds, %zu nodes\n",
              summary.progress.patches, mesh.elements.size(), summary.subdivisionRounds, mesh.nodes.size());
  EXPECT_GT(mesh.elements.size(), summary.progress.patches);
  EXPECT_LE(mesh.elements.size(), 3000u);
  validateMesh(mesh, "solved Cornell");
  for (const Node& node : mesh.nodes) EXPECT_TRUE(isFinite(node.B) && node.B.r >= 0 && node.B.g >= 0 && node.B.b >= 0);
  const MeshTopology topology(mesh);
  EXPECT_GT(topology.tVertices().size(), 0u);
  for (const TVertex& t : topology.tVertices()) {
    const auto& corners = mesh.elements[t.element].corners;
    EXPECT_EQ(std::count(corners.begin(), corners.end(), t.node), 0);
  }
  // The patches are cut along the blocks' footprints and leave out what the blocks cover
  // (cutAtContacts): no floor node lies under the short block, and the open floor is lit.
  const std::vector<Vec2> footprint = {{130, 65}, {82, 225}, {240, 272}, {290, 114}};  // (x, z)
  auto underBlock = [&](const Vec3& p) {
    for (size_t i = 0; i < 4; ++i) {
      const Vec2 a = footprint[i], b = footprint[(i + 1) % 4], q(p.x, p.z);
      if ((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x) > -1.0) return false;  // clockwise in (x, z)
    }
    return true;
  };
  size_t under = 0, openCount = 0;
  for (const Element& element : mesh.elements) {
    if (element.surface != 0) continue;  // the floor
    for (uint32_t node : element.corners) {
      const Vec3& p = mesh.nodes[node].position;
      under += underBlock(p);
      if (p.x > 350 && p.z < 200) {
        ++openCount;
        EXPECT_GT(mesh.nodes[node].B.g, 0.0);
      }
    }
  }
  EXPECT_EQ(under, 0u);
  ASSERT_GT(openCount, 0u);
  const std::string path = ::testing::TempDir() + "/solved_cornell.glb";
  writeSolution(mesh, path);
  const LoadedFile read = loadFile(path);
  ASSERT_TRUE(read.isSolution);
  ASSERT_EQ(read.mesh.elements.size(), mesh.elements.size());
  for (size_t e = 0; e < mesh.elements.size(); ++e) EXPECT_EQ(read.mesh.elements[e].order(), mesh.elements[e].order());
  EXPECT_EQ(MeshTopology(read.mesh).tVertices().size(), topology.tVertices().size());
  std::remove(path.c_str());

  // Baum et al.'s triangulation around the T-vertices removes them all.
  size_t repaired = 0;
  const RadiosityMesh triangulated = repairTVertices(mesh, &repaired);
  EXPECT_GT(repaired, 0u);
  EXPECT_EQ(MeshTopology(triangulated).tVertices().size(), 0u);
}

// The most T-vertex positions any element edge of `mesh` holds, on elements that 2:1 balance
// may split (longest edge at least twice `minElementSize`: the pieces of an element cut along a
// block's footprint can be smaller).
size_t mostTVerticesOnAnEdge(const RadiosityMesh& mesh, double minElementSize) {
  const MeshTopology topology(mesh);
  std::map<std::pair<uint32_t, uint32_t>, std::set<uint32_t>> perEdge;
  size_t most = 0;
  for (const TVertex& t : topology.tVertices()) {
    const std::vector<Vec3> corners = mesh.cornerPositions(t.element);
    double longest = 0.0;
    for (size_t i = 0; i < corners.size(); ++i)
      longest = std::max(longest, glm::distance(corners[i], corners[(i + 1) % corners.size()]));
    if (longest < 2.0 * minElementSize) continue;
    std::set<uint32_t>& positions = perEdge[{t.element, t.edge}];
    positions.insert(topology.positionId(t.node));
    most = std::max(most, positions.size());
  }
  return most;
}

// Without balance, subdivision leaves edges beside elements split two and more levels finer;
// with it (and room for it: the element cap is not reached), no edge holds more than one
// T-vertex, and the solution is the same to within the discretisation: the absorbed power
// agrees within 2 %.
TEST(AdaptiveSubdivisionTest, TwoToOneBalanceLeavesAtMostOneTVertexPerEdge) {
  SolveSummary plain, balanced;
  const RadiosityMesh unbalancedMesh = solvedCornell(false, plain, false, 20000);
  const RadiosityMesh balancedMesh = solvedCornell(false, balanced, true, 20000);
  ASSERT_LT(balancedMesh.elements.size(), 20000u);
  EXPECT_GE(mostTVerticesOnAnEdge(unbalancedMesh, 12.0), 2u);
  EXPECT_EQ(mostTVerticesOnAnEdge(balancedMesh, 12.0), 1u);
  validateMesh(balancedMesh, "balanced Cornell");
  const size_t plainT = MeshTopology(unbalancedMesh).tVertices().size();
  const size_t balancedT = MeshTopology(balancedMesh).tVertices().size();
  std::printf("Cornell, patches of 100 mm: %zu elements, %zu T-vertices; 2:1 balanced %zu elements, %zu T-vertices\n",
              unbalancedMesh.elements.size(), plainT, balancedMesh.elements.size(), balancedT);
  EXPECT_GT(balancedMesh.elements.size(), unbalancedMesh.elements.size());
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(balanced.energy.absorbed[k] / plain.energy.absorbed[k], 1.0, 0.02) << "channel " << k;
}

TEST(AdaptiveSubdivisionTest, QuadraticElementsShareTheirMidEdgeNodes) {
  SolveSummary summary;
  const RadiosityMesh mesh = solvedCornell(true, summary);
  validateMesh(mesh, "quadratic Cornell");
  for (const Element& element : mesh.elements) ASSERT_EQ(element.order(), ElementOrder::Quadratic);
  const MeshTopology topology(mesh);
  size_t interior = 0;
  for (const MeshEdge& edge : topology.edges()) {
    // Polygons meeting at a corner of the box share edge positions, not nodes.
    if (topology.sides(edge).size() != 2) continue;
    const EdgeSide s = topology.sides(edge)[0], t = topology.sides(edge)[1];
    if (mesh.elements[s.element].surface != mesh.elements[t.element].surface) continue;
    ++interior;
    EXPECT_EQ(mesh.elements[s.element].midEdge[s.edge], mesh.elements[t.element].midEdge[t.edge]);
  }
  EXPECT_GT(interior, 100u);
  EXPECT_GT(topology.tVertices().size(), 0u);
  for (const Node& node : mesh.nodes) EXPECT_TRUE(isFinite(node.B));
  const std::string path = ::testing::TempDir() + "/solved_quadratic.gltf";
  writeSolution(mesh, path);
  const LoadedFile read = loadFile(path);
  for (const Element& element : read.mesh.elements) EXPECT_EQ(element.order(), ElementOrder::Quadratic);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace radview
