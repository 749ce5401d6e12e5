// Retagging edges (edit/continuity_edit.h): the cycle C1 -> C0 -> C-1, node splitting along a
// C-1 line and joining back, undo, the file keeping the tags, and the Clough-Tocher values
// changing only in the elements at the retagged edges.
#include "edit/continuity_edit.h"

#include "core/error.h"
#include "import/load_file.h"
#include "interp/interpolant.h"
#include "mesh/solution_file.h"
#include "mesh/topology.h"
#include "tests/test_print.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>

namespace radview {
namespace {

constexpr int kCells = 6;

// kCells x kCells squares over [0,1]^2 in z = 0, each cut along the same diagonal, with smooth
// values that no interpolant reproduces exactly.
RadiosityMesh gridMesh() {
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"grey", Rgb(0.5), Rgb(0.0)});
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) {
      const double x = double(i) / kCells, y = double(j) / kCells;
      mesh.nodes.push_back({Vec3(x, y, 0.0), Rgb(1.0 + std::sin(3.0 * x) * y * y, 0.5 + x * y, 2.0 - x * x), {}});
    }
  auto id = [](int i, int j) { return uint32_t(j * (kCells + 1) + i); };
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) {
      mesh.elements.push_back(Element{{id(i, j), id(i + 1, j), id(i + 1, j + 1)}, {}, 0, 0});
      mesh.elements.push_back(Element{{id(i, j), id(i + 1, j + 1), id(i, j + 1)}, {}, 0, 0});
    }
  return mesh;
}

// The element edges on the line x = 1/2, bottom to top, each named from its left element.
std::vector<EdgeRef> middleLine(const RadiosityMesh& mesh) {
  std::vector<EdgeRef> line;
  for (uint32_t e = 0; e < mesh.elements.size(); ++e)
    for (uint32_t k = 0; k < 3; ++k) {
      const Vec3 a = mesh.nodes[mesh.elements[e].corners[k]].position;
      const Vec3 b = mesh.nodes[mesh.elements[e].corners[(k + 1) % 3]].position;
      const Vec3 centroid =
          (mesh.nodes[mesh.elements[e].corners[0]].position + mesh.nodes[mesh.elements[e].corners[1]].position +
           mesh.nodes[mesh.elements[e].corners[2]].position) /
          3.0;
      if (a.x == 0.5 && b.x == 0.5 && centroid.x < 0.5) line.push_back({e, k});
    }
  return line;
}

bool centroidLeft(const RadiosityMesh& mesh, uint32_t element) {
  double x = 0.0;
  for (const Vec3& p : mesh.cornerPositions(element)) x += p.x / 3.0;
  return x < 0.5;
}

bool touchesTheLine(const RadiosityMesh& mesh, uint32_t element) {
  for (uint32_t n : mesh.elements[element].corners)
    if (mesh.nodes[n].position.x == 0.5) return true;
  return false;
}

// Clough-Tocher's value at a few points of every element.
std::vector<Rgb> cloughTocherValues(const RadiosityMesh& mesh) {
  const auto interpolant = makeInterpolant(mesh, Method::CloughTocher);
  std::vector<Rgb> values;
  for (uint32_t e = 0; e < mesh.elements.size(); ++e) {
    const auto p = mesh.cornerPositions(e);
    for (const Vec3& w : {Vec3(1, 1, 1) / 3.0, Vec3(0.6, 0.3, 0.1), Vec3(0.1, 0.45, 0.45), Vec3(0.45, 0.1, 0.45)})
      values.push_back(interpolant->evaluate(e, w.x * p[0] + w.y * p[1] + w.z * p[2]).B);
  }
  return values;
}

void setLine(RadiosityMesh& mesh, const std::vector<EdgeRef>& line, Continuity order) {
  for (const EdgeRef& edge : line) setEdgeContinuity(mesh, edge, order);
}

TEST(ContinuityEdit, AClickCyclesC1C0Cm1AndBackToC1) {
  RadiosityMesh mesh = gridMesh();
  const EdgeRef edge = middleLine(mesh)[2];
  ContinuityEditor editor;
  for (Continuity expected : {Continuity::C0, Continuity::Cm1, Continuity::C1}) {
    EXPECT_FALSE(editor.cycle(mesh, {edge}).has_value());
    validateMesh(mesh, "edited");
    EXPECT_EQ(describeEdge(mesh, MeshTopology(mesh), edge).continuity, expected);
  }
  EXPECT_EQ(editor.steps(), 3u);
}

// The topology the editor keeps from edit to edit (updated in place for a retag, built again
// for a split or a join) is the edited mesh's, field by field, after every click and undo.
TEST(ContinuityEdit, TheEditorsTopologyIsTheEditedMeshs) {
  RadiosityMesh mesh = gridMesh();
  mesh.discontinuities.push_back({3, 4, Continuity::C0});  // a boundary edge tagged before any edit
  const std::vector<EdgeRef> line = middleLine(mesh);
  ContinuityEditor editor;
  auto expectCurrent = [&](const std::string& after) {
    const std::shared_ptr<const MeshTopology> shared = editor.topology(mesh);  // held: the next edit copies it
    const MeshTopology& kept = *shared;
    const MeshTopology fresh(mesh);
    ASSERT_EQ(kept.positionCount(), fresh.positionCount()) << after;
    for (uint32_t n = 0; n < mesh.nodes.size(); ++n) ASSERT_EQ(kept.positionId(n), fresh.positionId(n)) << after;
    ASSERT_EQ(kept.edges().size(), fresh.edges().size()) << after;
    for (size_t i = 0; i < fresh.edges().size(); ++i) {
      const MeshEdge &k = kept.edges()[i], &f = fresh.edges()[i];
      EXPECT_TRUE(k.a == f.a && k.b == f.b && k.firstSide == f.firstSide && k.sideCount == f.sideCount &&
                  k.continuity == f.continuity)
          << after << ": edge " << i;
    }
    for (uint32_t e = 0; e < mesh.elements.size(); ++e)
      for (uint32_t k = 0; k < 3; ++k) EXPECT_EQ(kept.edgeIndex(e, k), fresh.edgeIndex(e, k)) << after;
    EXPECT_EQ(kept.tVertices().size(), fresh.tVertices().size()) << after;
  };
  // Clicks on one edge (C0, C-1: a split, C1: a join), a drag along the line (C0), then again
  // (C-1: splits), each undone in turn.
  // Started from a renderer's topology, which keeps what it holds.
  editor.startFrom(std::make_shared<const MeshTopology>(mesh));
  const std::shared_ptr<const MeshTopology> held = editor.topology(mesh);
  const size_t heldC0 = held->countEdges(Continuity::C0);
  for (int click = 0; click < 3; ++click) {
    editor.cycle(mesh, {line[2]});
    expectCurrent("click " + std::to_string(click));
  }
  EXPECT_EQ(held->countEdges(Continuity::C0), heldC0);
  editor.cycle(mesh, line);
  expectCurrent("the line C0");
  editor.cycle(mesh, line);
  expectCurrent("the line C-1");
  while (editor.undo(mesh)) expectCurrent("undo, " + std::to_string(editor.steps()) + " steps left");
}

TEST(ContinuityEdit, CloughTocherChangesOnlyInTheElementsAtTheRetaggedEdges) {
  RadiosityMesh mesh = gridMesh();
  const std::vector<Rgb> before = cloughTocherValues(mesh);
  for (Continuity order : {Continuity::C0, Continuity::Cm1}) {
    RadiosityMesh edited = mesh;
    setLine(edited, middleLine(edited), order);
    const std::vector<Rgb> after = cloughTocherValues(edited);
    size_t changedNearTheLine = 0;
    for (uint32_t e = 0; e < mesh.elements.size(); ++e)
      for (size_t k = 4 * e; k < 4 * e + 4; ++k) {
        if (!touchesTheLine(mesh, e)) {
          EXPECT_EQ(after[k], before[k]) << toString(order) << ": element " << e << " is away from the line";
        } else if (glm::length(after[k] - before[k]) > 1e-6) {
          ++changedNearTheLine;
        }
      }
    EXPECT_GT(changedNearTheLine, 20u) << toString(order) << ": the line's own elements lose their C1 link";
  }
}

TEST(ContinuityEdit, Cm1AcrossTheMeshSplitsItsNodesAndUndoJoinsThemBack) {
  const RadiosityMesh original = gridMesh();
  RadiosityMesh mesh = original;
  const std::vector<EdgeRef> line = middleLine(mesh);
  ASSERT_EQ(line.size(), size_t(kCells));
  ContinuityEditor editor;
  editor.cycle(mesh, line);  // C0: only tags
  EXPECT_EQ(mesh.nodes.size(), original.nodes.size());
  EXPECT_EQ(MeshTopology(mesh).countEdges(Continuity::C0), size_t(kCells));
  editor.cycle(mesh, line);  // C-1: the line cuts the square in two, so each of its nodes splits
  validateMesh(mesh, "edited");
  EXPECT_EQ(mesh.nodes.size(), original.nodes.size() + kCells + 1);
  const MeshTopology topology(mesh);
  EXPECT_EQ(topology.countEdges(Continuity::Cm1), size_t(kCells));
  for (const EdgeRef& edge : line) EXPECT_TRUE(describeEdge(mesh, topology, edge).ownNodes);
  // Every corner keeps its value, and no node on the line is used on both of its sides.
  std::set<uint32_t> left, right;
  for (uint32_t e = 0; e < mesh.elements.size(); ++e)
    for (size_t k = 0; k < 3; ++k) {
      const uint32_t n = mesh.elements[e].corners[k];
      EXPECT_EQ(mesh.nodes[n].B, original.nodes[original.elements[e].corners[k]].B);
      if (mesh.nodes[n].position.x == 0.5) (centroidLeft(mesh, e) ? left : right).insert(n);
    }
  for (uint32_t n : left) EXPECT_EQ(right.count(n), 0u) << "node " << n << " is on both sides of the C-1 line";

  ASSERT_TRUE(editor.undo(mesh));
  ASSERT_TRUE(editor.undo(mesh));
  EXPECT_FALSE(editor.undo(mesh));
  ASSERT_EQ(mesh.nodes.size(), original.nodes.size());
  for (size_t n = 0; n < mesh.nodes.size(); ++n) EXPECT_EQ(mesh.nodes[n].position, original.nodes[n].position);
  for (size_t e = 0; e < mesh.elements.size(); ++e) EXPECT_EQ(mesh.elements[e].corners, original.elements[e].corners);
  EXPECT_TRUE(mesh.discontinuities.empty());
}

TEST(ContinuityEdit, ASingleCm1EdgeInsideKeepsItsSharedNodes) {
  // One interior edge cannot cut the elements around either end in two: nothing to split.
  RadiosityMesh mesh = gridMesh();
  const EdgeRef edge = middleLine(mesh)[3];
  setEdgeContinuity(mesh, edge, Continuity::Cm1);
  EXPECT_EQ(mesh.nodes.size(), gridMesh().nodes.size());
  const EdgeDescription d = describeEdge(mesh, MeshTopology(mesh), edge);
  EXPECT_EQ(d.continuity, Continuity::Cm1);
  EXPECT_FALSE(d.ownNodes);
}

TEST(ContinuityEdit, ElementsMeetingThroughATVertexStayJoinedAtTheirNode) {
  // t_vertices.gltf: the fine quads' edge (0.5, 0.5)-(0.75, 0.5) made C-1. Around (0.5, 0.5) the
  // coarse quads' long edges meet the fine quads' short ones through the T-vertices, so the
  // elements there still go round the node: nothing is cut apart, no node is split.
  RadiosityMesh mesh = loadFile(RADVIEW_SOURCE_DIR "/assets/t_vertices.gltf").mesh;
  const size_t nodes = mesh.nodes.size();
  std::optional<EdgeRef> edge;
  for (uint32_t e = 0; e < mesh.elements.size() && !edge; ++e)
    for (uint32_t k = 0; k < mesh.elements[e].corners.size(); ++k) {
      const Vec3 a = mesh.nodes[mesh.elements[e].corners[k]].position;
      const Vec3 b = mesh.nodes[mesh.elements[e].corners[(k + 1) % mesh.elements[e].corners.size()]].position;
      if (std::min(a.x, b.x) == 0.5 && std::max(a.x, b.x) == 0.75 && a.y == 0.5 && b.y == 0.5) edge = EdgeRef{e, k};
    }
  ASSERT_TRUE(edge.has_value());
  setEdgeContinuity(mesh, *edge, Continuity::Cm1);
  EXPECT_EQ(mesh.nodes.size(), nodes);
  EXPECT_EQ(describeEdge(mesh, MeshTopology(mesh), *edge).continuity, Continuity::Cm1);
}

TEST(ContinuityEdit, JoiningSidesWithDifferentRadiositiesIsRefusedAndChangesNothing) {
  RadiosityMesh mesh = gridMesh();
  const std::vector<EdgeRef> line = middleLine(mesh);
  setLine(mesh, line, Continuity::Cm1);
  mesh.nodes.back().B += Rgb(0.25);  // a copy made by the split: now a real jump
  const RadiosityMesh before = mesh;
  bool refused = false;
  for (const EdgeRef& edge : line) {
    try {
      setEdgeContinuity(mesh, edge, Continuity::C1);
    } catch (const Error& e) {
      refused = true;
      EXPECT_NE(std::string(e.what()).find("different radiosities"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(refused);
  validateMesh(mesh, "edited");
  // The refused edges are still C-1; the node with its own value is still there.
  EXPECT_GE(MeshTopology(mesh).countEdges(Continuity::Cm1), 1u);
  bool stillThere = false;
  for (const Node& n : mesh.nodes) stillThere |= n.B == before.nodes.back().B;
  EXPECT_TRUE(stillThere);
}

TEST(ContinuityEdit, AWrittenSolutionReadsBackWithItsNewTags) {
  RadiosityMesh mesh = gridMesh();
  const std::vector<EdgeRef> line = middleLine(mesh);
  setLine(mesh, line, Continuity::Cm1);
  setEdgeContinuity(mesh, {0, 0}, Continuity::C0);  // a boundary edge: a tag only
  const std::string path = (std::filesystem::temp_directory_path() / "radview_continuity_edit.glb").string();
  writeSolution(mesh, path);
  const RadiosityMesh read = loadFile(path).mesh;
  std::filesystem::remove(path);
  EXPECT_EQ(read.nodes.size(), mesh.nodes.size());
  const MeshTopology topology(read);
  EXPECT_EQ(topology.countEdges(Continuity::Cm1), size_t(kCells));
  EXPECT_EQ(topology.countEdges(Continuity::C0), 1u);
  // The file holds float32 positions and radiosities.
  const std::vector<Rgb> readValues = cloughTocherValues(read), values = cloughTocherValues(mesh);
  ASSERT_EQ(readValues.size(), values.size());
  for (size_t i = 0; i < values.size(); ++i) EXPECT_LT(glm::length(readValues[i] - values[i]), 1e-6) << i;
}

TEST(ContinuityEdit, AnEdgeThatDoesNotExistIsAClearError) {
  RadiosityMesh mesh = gridMesh();
  EXPECT_THROW(setEdgeContinuity(mesh, {uint32_t(mesh.elements.size()), 0}, Continuity::C0), Error);
  EXPECT_THROW(setEdgeContinuity(mesh, {0, 3}, Continuity::C0), Error);
}

}  // namespace
}  // namespace radview
