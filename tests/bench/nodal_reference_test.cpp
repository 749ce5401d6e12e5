// The reference at the nodes (renderer/bench/nodal_reference.h): eq. 9.9 and the path tracer
// evaluated there agree with a closed form, and only the nodes a view depends on are gathered.
#include "bench/nodal_reference.h"

#include "mesh/uniform_mesher.h"
#include "tests/closed_form_scenes.h"
#include "trace/visible_elements.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace radview {
namespace {

RadiosityMesh closedFormMesh(const test::ClosedFormScene& scene, double elementSize) {
  RadiosityMesh mesh = meshUniformly(scene.scene, elementSize);
  for (const Element& e : mesh.elements)
    for (uint32_t n : e.corners)
      mesh.nodes[n].B = e.material == 1 ? scene.E : Rgb(0.0);  // the receiver's to be gathered
  return mesh;
}

TEST(NodalReference, EachRunAtEachNodeEstimatesTheClosedForm) {
  const test::ClosedFormScene scene = test::emitterOverSquare(30.0);
  const RadiosityMesh mesh = closedFormMesh(scene, 0.25);
  GatherSettings settings;
  settings.runs = 4;
  const FinalGather gather(mesh, settings);
  const NodalReference reference = gatherAtNodes(mesh, gather, 1024);
  ASSERT_EQ(reference.runs, 4);
  double worst = 0.0;
  size_t receiverNodes = 0;
  for (size_t n = 0; n < mesh.nodes.size(); ++n) {
    if (std::abs(mesh.nodes[n].position.y) > 1e-12) continue;  // the emitter's
    ++receiverNodes;
    const double exact = scene.B(mesh.nodes[n].position).r;
    double mean = 0.0;
    for (int r = 0; r < 4; ++r) mean += reference.B[n * 4 + size_t(r)].r / 4.0;
    worst = std::max(worst, std::abs(mean - exact) / exact);
  }
  std::printf("%zu receiver nodes, 4096 samples each: largest relative error %.2e\n", receiverNodes, worst);
  EXPECT_EQ(receiverNodes, 25u);
  // Direct light only, from a small emitter, unoccluded: the nodes' own limit.
  EXPECT_LT(worst, 0.005);
  // A copy holding one run's values, the mesh otherwise the same.
  const RadiosityMesh run = reference.withRun(mesh, 2);
  EXPECT_EQ(run.elements.size(), mesh.elements.size());
  EXPECT_EQ(run.nodes[0].B, reference.B[0 * 4 + 2]);
}

TEST(NodalReference, PathTracedAtEachNodeEstimatesTheClosedForm) {
  // The truth at the nodes needs no solution: the mesh's B is left at zero on the receiver.
  const test::ClosedFormScene scene = test::emitterOverSquare(30.0);
  const RadiosityMesh mesh = closedFormMesh(scene, 0.25);
  PathTraceSettings settings;
  settings.runs = 4;
  const PathTracer tracer(elementScene(mesh), settings);
  const NodalReference reference = pathTraceAtNodes(mesh, tracer, 1024);
  ASSERT_EQ(reference.runs, 4);
  double worst = 0.0;
  size_t receiverNodes = 0;
  for (size_t n = 0; n < mesh.nodes.size(); ++n) {
    if (std::abs(mesh.nodes[n].position.y) > 1e-12) continue;
    ++receiverNodes;
    const double exact = scene.B(mesh.nodes[n].position).r;
    double mean = 0.0;
    for (int r = 0; r < 4; ++r) mean += reference.B[n * 4 + size_t(r)].r / 4.0;
    worst = std::max(worst, std::abs(mean - exact) / exact);
  }
  std::printf("%zu receiver nodes, 4096 paths each: largest relative error %.2e\n", receiverNodes, worst);
  EXPECT_EQ(receiverNodes, 25u);
  // Each node's standard error is about 0.3 % here; a wrong pdf or weight is off by far more.
  EXPECT_LT(worst, 0.015);
}

TEST(NodalReference, OnlyTheNodesOfTheElementsSeenAndTheirNeighbours) {
  const test::ClosedFormScene scene = test::emitterOverSquare();
  const RadiosityMesh mesh = closedFormMesh(scene, 0.25);  // a 4 x 4 grid of quads, and the emitter
  // The view sees one corner element of the receiver.
  size_t seen = 0;
  while (mesh.elements[seen].material != 0) ++seen;
  const std::vector<char> wanted = nodesOfTheView(mesh, {-1, int32_t(seen), -1});
  size_t count = 0;
  for (char w : wanted) count += w;
  // Its 4 nodes, and those of the elements that share one of them: a 3 x 3 block of quads
  // around a corner quad is at most 16 nodes, at least the corner quad's 2 x 2 neighbourhood's 9.
  EXPECT_GE(count, 9u);
  EXPECT_LE(count, 16u);
  for (uint32_t n : mesh.elements[seen].corners) EXPECT_TRUE(wanted[n]);
  // A node nobody sees keeps its value, the emitter's.
  GatherSettings settings;
  settings.runs = 4;
  const FinalGather gather(mesh, settings);
  const NodalReference reference = gatherAtNodes(mesh, gather, 4, wanted);
  for (size_t n = 0; n < mesh.nodes.size(); ++n) {
    if (!wanted[n]) {
      EXPECT_EQ(reference.B[n * 4], mesh.nodes[n].B) << n;
    }
  }
}

}  // namespace
}  // namespace radview
