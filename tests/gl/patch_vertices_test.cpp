// The Bezier pieces as the GPU receives them (renderer/gl/patch_vertices.h), and the control
// net of the radiosity surface built from them. No GL context needed.
#include "gl/patch_vertices.h"
#include "interp/c1_patches.h"
#include "tests/interp/test_meshes.h"

#include <gtest/gtest.h>

namespace radview::gl {
namespace {

// A jittered triangle mesh in a tilted plane, B a linear function of position.
RadiosityMesh linearFieldMesh() {
  const test::Field f = [](const Vec2& p) {
    return Rgb(0.2 + 0.5 * p.x + 0.1 * p.y, 0.4 - 0.2 * p.y, 0.3 + 0.3 * p.x);
  };
  return test::gridMesh(4, false, 0.3, f, 7);
}

// Every piece, as (pieces, degree), for both C1 methods.
std::vector<std::pair<std::vector<BezierVertex>, int>> c1Pieces(const RadiosityMesh& mesh) {
  const SurfaceTriangulation surface(mesh);
  const CornerGradients gradients = vertexGradients(surface, true);
  return {
      {powellSabinVertices(buildPowellSabinPatches(surface, gradients)), 2},
      {cloughTocherVertices(buildCloughTocherPatches(surface, gradients, CloughTocherVariant::AffineInvariant)), 3}};
}

// The radiosity surface lifts each piece along its corners' right-hand normal: every piece must
// turn the way the mesh does, or neighbouring pieces are lifted to opposite sides (Powell-Sabin
// pieces alternate in orientation as the split makes them).
TEST(PatchVertices, EveryPieceTurnsTheWayItsElementDoes) {
  const RadiosityMesh mesh = linearFieldMesh();
  const glm::vec3 meshNormal(mesh.elementNormal(0));
  for (const auto& [pieces, degree] : c1Pieces(mesh)) {
    ASSERT_FALSE(pieces.empty());
    for (size_t first = 0; first < pieces.size(); first += 3) {
      const glm::vec3 n = glm::cross(pieces[first + 1].position - pieces[first].position,
                                     pieces[first + 2].position - pieces[first].position);
      EXPECT_GT(glm::dot(n, meshNormal), 0.0f) << "degree " << degree << ", piece " << first / 3;
    }
  }
}

// A linear field is reproduced by both C1 methods, so the radiosity surface is the plane of the
// lifted corners, and so is every point of its control net (lifting is linear in B).
TEST(PatchVertices, ControlNetOfALinearFieldLiesOnTheLiftedPlane) {
  const RadiosityMesh mesh = linearFieldMesh();
  const double height = 0.7;
  const glm::dvec3 luminance(0.2126, 0.7152, 0.0722);
  auto lifted = [&](size_t node) {
    return mesh.nodes[node].position + mesh.elementNormal(0) * height * glm::dot(mesh.nodes[node].B, luminance);
  };
  const Vec3 a = lifted(0), b = lifted(4), c = lifted(20);  // three corners of the 4x4 grid
  const Vec3 planeNormal = glm::normalize(glm::cross(b - a, c - a));
  for (const auto& [pieces, degree] : c1Pieces(mesh)) {
    const std::vector<glm::vec3> net = controlNetLines(pieces, degree, height);
    // Segments per piece: 3 per row step, n (n + 1) / 2 * 3 in all.
    EXPECT_EQ(net.size(), pieces.size() / 3 * size_t(degree * (degree + 1) / 2 * 3) * 2);
    double worst = 0.0;
    for (const glm::vec3& p : net) worst = std::max(worst, std::abs(glm::dot(Vec3(p) - a, planeNormal)));
    EXPECT_LT(worst, 2e-6) << "degree " << degree;
  }
}

// The net's corner points are the element corners lifted by their own B.
TEST(PatchVertices, ControlNetCornersAreTheLiftedNodes) {
  const RadiosityMesh mesh = linearFieldMesh();
  const auto pieces = c1Pieces(mesh)[1].first;  // Clough-Tocher: piece k starts at corner V_k
  const std::vector<glm::vec3> net = controlNetLines(pieces, 3, 1.0);
  const Vec3 n = mesh.elementNormal(0);
  // The first segment starts at b_300 of the first piece, its first corner.
  size_t node = 0;
  for (; node < mesh.nodes.size(); ++node)
    if (glm::distance(glm::vec3(mesh.nodes[node].position), pieces[0].position) < 1e-6f) break;
  ASSERT_LT(node, mesh.nodes.size());
  const Vec3 expected = mesh.nodes[node].position + n * glm::dot(mesh.nodes[node].B, Rgb(0.2126, 0.7152, 0.0722));
  EXPECT_LT(glm::distance(Vec3(net[0]), expected), 1e-6);
}

}  // namespace
}  // namespace radview::gl
