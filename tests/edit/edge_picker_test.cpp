// Picking element edges in a view (edit/edge_picker.h): a pixel on an edge names it, a pixel in
// the middle of an element or on the background names none, and a stroke names each edge it
// crosses once.
#include "edit/edge_picker.h"

#include "mesh/topology.h"
#include "tests/test_print.h"

#include <gtest/gtest.h>

#include <set>

namespace radview {
namespace {

// Two triangles making the unit square in z = 0, cut along (0,0)-(1,1).
RadiosityMesh square() {
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"grey", Rgb(0.5), Rgb(0.0)});
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)})
    mesh.nodes.push_back({p, Rgb(1.0), {}});
  mesh.elements.push_back(Element{{0, 1, 2}, {}, 0, 0});
  mesh.elements.push_back(Element{{0, 2, 3}, {}, 0, 0});
  return mesh;
}

constexpr int kSize = 200;

Camera above() {
  Camera c;
  c.eye = Vec3(0.5, 0.5, 2.0);
  c.target = Vec3(0.5, 0.5, 0.0);
  c.up = Vec3(0, 1, 0);
  fitClipPlanes(c, Bounds{Vec3(0), Vec3(1, 1, 0)});
  return c;
}

// Where a world point appears, in pixels from the top left.
std::pair<double, double> pixelOf(const Camera& c, const Vec3& p) {
  const glm::dvec4 clip = c.clipFromWorld(1.0) * glm::dvec4(p, 1.0);
  return {(clip.x / clip.w + 1.0) * 0.5 * kSize, (1.0 - clip.y / clip.w) * 0.5 * kSize};
}

// The positions of an edge's ends, lowest first, to compare picks made from either side.
std::pair<Vec3, Vec3> ends(const RadiosityMesh& mesh, EdgeRef e) {
  const Element& element = mesh.elements[e.element];
  Vec3 a = mesh.nodes[element.corners[e.edge]].position;
  Vec3 b = mesh.nodes[element.corners[(e.edge + 1) % element.corners.size()]].position;
  if (b.x < a.x || (b.x == a.x && b.y < a.y)) std::swap(a, b);
  return {a, b};
}

TEST(EdgePicker, APixelOnAnEdgeNamesItAndOneInsideOrOutsideNamesNone) {
  const RadiosityMesh mesh = square();
  const EdgePicker picker(mesh);
  const Camera camera = above();
  const auto [dx, dy] = pixelOf(camera, Vec3(0.5, 0.5, 0.0));  // on the diagonal
  const std::optional<EdgeRef> diagonal = picker.pick(camera, kSize, kSize, dx + 1.5, dy - 1.0);
  ASSERT_TRUE(diagonal.has_value());
  EXPECT_EQ(ends(mesh, *diagonal), std::pair(Vec3(0, 0, 0), Vec3(1, 1, 0)));
  const auto [bx, by] = pixelOf(camera, Vec3(0.5, 0.02, 0.0));  // near the bottom edge
  const std::optional<EdgeRef> bottom = picker.pick(camera, kSize, kSize, bx, by);
  ASSERT_TRUE(bottom.has_value());
  EXPECT_EQ(ends(mesh, *bottom), std::pair(Vec3(0, 0, 0), Vec3(1, 0, 0)));
  const auto [ix, iy] = pixelOf(camera, Vec3(0.75, 0.3, 0.0));  // inside the lower triangle
  EXPECT_FALSE(picker.pick(camera, kSize, kSize, ix, iy).has_value());
  EXPECT_FALSE(picker.pick(camera, kSize, kSize, 2.0, 2.0).has_value());  // the background
}

TEST(EdgePicker, AStrokeAcrossTheSquareNamesTheEdgesItCrosses) {
  const RadiosityMesh mesh = square();
  const EdgePicker picker(mesh);
  const Camera camera = above();
  // From inside the lower triangle, across the diagonal, to inside the upper one.
  const std::vector<EdgeRef> crossed = picker.pickAlong(
      camera, kSize, kSize, {pixelOf(camera, Vec3(0.7, 0.3, 0.0)), pixelOf(camera, Vec3(0.3, 0.7, 0.0))});
  ASSERT_FALSE(crossed.empty());
  const MeshTopology topology(mesh);
  std::set<uint32_t> edges;
  for (const EdgeRef& e : crossed) edges.insert(topology.edgeIndex(e.element, e.edge));
  EXPECT_EQ(edges.size(), 1u) << "only the diagonal, from either side";
  EXPECT_EQ(ends(mesh, crossed[0]), std::pair(Vec3(0, 0, 0), Vec3(1, 1, 0)));
}

}  // namespace
}  // namespace radview
