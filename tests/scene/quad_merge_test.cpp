#include "scene/quad_merge.h"

#include "geom/polygon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace radview {
namespace {

Scene sceneOf(const std::vector<std::vector<Vec3>>& triangles, int materials = 1) {
  Scene scene;
  scene.materials.resize(materials);
  for (const auto& t : triangles) scene.polygons.push_back({t, 0});
  return scene;
}

// glTF's split of the quad a b c d: (a, b, c) and (a, c, d).
std::vector<std::vector<Vec3>> split(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return {{a, b, c}, {a, c, d}};
}

// True if `polygon` is `expected` up to the starting vertex.
bool sameCycle(const std::vector<Vec3>& polygon, const std::vector<Vec3>& expected) {
  if (polygon.size() != expected.size()) return false;
  for (size_t shift = 0; shift < polygon.size(); ++shift) {
    std::vector<Vec3> rotated = polygon;
    std::rotate(rotated.begin(), rotated.begin() + shift, rotated.end());
    if (rotated == expected) return true;
  }
  return false;
}

TEST(QuadMergeTest, GltfStyleQuadBecomesTheQuad) {
  const std::vector<Vec3> quad{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
  const Scene merged = mergeTrianglesIntoQuads(sceneOf(split(quad[0], quad[1], quad[2], quad[3])));
  ASSERT_EQ(merged.polygons.size(), 1u);
  EXPECT_EQ(merged.polygons[0].vertices, quad);  // starts at the first triangle's first vertex
}

TEST(QuadMergeTest, ResultDoesNotDependOnHowTrianglesListTheirVertices) {
  const std::vector<Vec3> quad{{0, 0, 0}, {2, 0.2, 0}, {2.5, 1, 0.3}, {-0.2, 1.2, 0.488}};  // planar
  for (int r0 = 0; r0 < 3; ++r0)
    for (int r1 = 0; r1 < 3; ++r1)
      for (bool swapOrder : {false, true}) {
        auto triangles = split(quad[0], quad[1], quad[2], quad[3]);
        std::rotate(triangles[0].begin(), triangles[0].begin() + r0, triangles[0].end());
        std::rotate(triangles[1].begin(), triangles[1].begin() + r1, triangles[1].end());
        if (swapOrder) std::swap(triangles[0], triangles[1]);
        const Scene merged = mergeTrianglesIntoQuads(sceneOf(triangles));
        ASSERT_EQ(merged.polygons.size(), 1u);
        EXPECT_TRUE(sameCycle(merged.polygons[0].vertices, quad)) << r0 << ' ' << r1 << ' ' << swapOrder;
        EXPECT_EQ(merged.polygons[0].vertices[0], triangles[0][0]);
      }
}

TEST(QuadMergeTest, FoldedPairStaysTriangles) {
  const Scene folded = sceneOf(split({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.1}));
  EXPECT_EQ(mergeTrianglesIntoQuads(folded).polygons.size(), 2u);
}

// The Cornell box's red wall: 549.6..556 mm wide at the bottom and top, its fourth corner
// about 3 mm off the plane of the other three (see corpus/cornell-box-data.md).
TEST(QuadMergeTest, SkewedCornellRedWallStaysTriangles) {
  const Vec3 a{552.8, 0, 0}, b{549.6, 0, 559.2}, c{556, 548.8, 559.2}, d{556, 548.8, 0};
  const Scene wall = sceneOf(split(a, b, c, d));
  EXPECT_GT(planarityError({a, b, c, d}), 0.5);
  EXPECT_EQ(mergeTrianglesIntoQuads(wall).polygons.size(), 2u);
  EXPECT_EQ(mergeTrianglesIntoQuads(wall, 1e-2).polygons.size(), 1u);  // a loose tolerance takes it
}

TEST(QuadMergeTest, ConcaveOrDegenerateUnionStaysTriangles) {
  // A dart: (0,0) (2,1) (0,2) with the notch (0.5,1).
  const Scene dart = sceneOf({{{0, 0, 0}, {2, 1, 0}, {0.5, 1, 0}}, {{0.5, 1, 0}, {2, 1, 0}, {0, 2, 0}}});
  EXPECT_EQ(mergeTrianglesIntoQuads(dart).polygons.size(), 2u);
  // A triangle cut along a median: the union has a straight angle.
  const Scene halves = sceneOf({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {2, 0, 0}, {0, 1, 0}}});
  EXPECT_EQ(mergeTrianglesIntoQuads(halves).polygons.size(), 2u);
}

TEST(QuadMergeTest, DifferentMaterialsOrFacingsStayTriangles) {
  Scene scene = sceneOf(split({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}), 2);
  scene.polygons[1].material = 1;
  EXPECT_EQ(mergeTrianglesIntoQuads(scene).polygons.size(), 2u);
  // The second triangle flipped: the shared edge runs the same way in both.
  Scene flipped = sceneOf(split({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}));
  std::reverse(flipped.polygons[1].vertices.begin(), flipped.polygons[1].vertices.end());
  EXPECT_EQ(mergeTrianglesIntoQuads(flipped).polygons.size(), 2u);
}

TEST(QuadMergeTest, OnlyMutualLongestEdgePartnersMerge) {
  // A strip t0, t1, t2: t0's only partner is t1, but t1's longest mergeable edge is the one it
  // shares with t2, and t2's only partner is t1. So t1 + t2 merge and t0 stays.
  const Vec3 P0{0, 0, 0}, P1{1, 0, 0}, P2{0, 1, 0}, P3{2.5, 1, 0}, P4{3, 0, 0};
  Scene strip = sceneOf({{P0, P1, P2}, {P1, P3, P2}, {P1, P4, P3}});
  const Scene merged = mergeTrianglesIntoQuads(strip);
  ASSERT_EQ(merged.polygons.size(), 2u);
  EXPECT_EQ(merged.polygons[0].vertices, (std::vector<Vec3>{P0, P1, P2}));
  EXPECT_TRUE(sameCycle(merged.polygons[1].vertices, {P1, P4, P3, P2}));
}

TEST(QuadMergeTest, ShuffledGridOfSplitSquaresGivesBackTheSquares) {
  std::mt19937 rng(3);
  Scene scene;
  scene.materials.resize(1);
  std::vector<std::vector<Vec3>> squares;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j) {
      const Vec3 a(i, j, 0), b(i + 1, j, 0), c(i + 1, j + 1, 0), d(i, j + 1, 0);
      squares.push_back({a, b, c, d});
      // Alternate the diagonal, as exporters do.
      for (auto& t : (i + j) % 2 ? split(a, b, c, d) : split(b, c, d, a)) {
        std::rotate(t.begin(), t.begin() + rng() % 3, t.end());
        scene.polygons.push_back({t, 0});
      }
    }
  scene.polygons.push_back({{{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0.5, 1.5, 1}, {0, 1, 1}}, 0});  // a pentagon
  std::shuffle(scene.polygons.begin(), scene.polygons.end(), rng);
  const Scene merged = mergeTrianglesIntoQuads(scene);
  ASSERT_EQ(merged.polygons.size(), squares.size() + 1);
  size_t found = 0;
  for (const Polygon& p : merged.polygons) {
    if (p.vertices.size() == 5) continue;
    found += std::count_if(squares.begin(), squares.end(), [&](const auto& s) { return sameCycle(p.vertices, s); });
  }
  EXPECT_EQ(found, squares.size());
}

}  // namespace
}  // namespace radview
