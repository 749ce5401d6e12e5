// Shooting patches grouped from a discontinuity mesh: what the groups are, and that shooting
// from them solves the same scene as shooting from every triangle.
#include "solve/shooting_patches.h"

#include "core/error.h"
#include "discontinuity/discontinuity_mesher.h"
#include "geom/polygon.h"
#include "mesh/uniform_mesher.h"
#include "solve/progressive_refinement.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace radview {
namespace {

using Quad = std::vector<Vec3>;

// A square light over a floor with a cube between them: shadow boundaries cut the floor and
// the cube's sides into many small triangles.
Scene cubeUnderALight() {
  Scene scene;
  scene.materials = {{"white", {0.6, 0.6, 0.6}, {0, 0, 0}}, {"light", {0, 0, 0}, {10, 10, 10}}};
  scene.polygons.push_back({{{-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}}, 0});
  scene.polygons.push_back({{{-0.5, -0.5, 3}, {-0.5, 0.5, 3}, {0.5, 0.5, 3}, {0.5, -0.5, 3}}, 1});
  const double a = -0.4, b = 0.4, h = 0.8, z = 0.6;  // a cube floating at z .. z + h
  const std::vector<Quad> cube = {{{a, a, z + h}, {b, a, z + h}, {b, b, z + h}, {a, b, z + h}},
                                  {{a, a, z}, {a, b, z}, {b, b, z}, {b, a, z}},
                                  {{a, a, z}, {b, a, z}, {b, a, z + h}, {a, a, z + h}},
                                  {{b, a, z}, {b, b, z}, {b, b, z + h}, {b, a, z + h}},
                                  {{b, b, z}, {a, b, z}, {a, b, z + h}, {b, b, z + h}},
                                  {{a, b, z}, {a, a, z}, {a, a, z + h}, {a, b, z + h}}};
  for (const Quad& q : cube) scene.polygons.push_back({q, 0});
  return scene;
}

TEST(ShootingPatchesTest, GroupsElementsOfOneSurfaceAndMaterialWithinACell) {
  const Scene scene = cubeUnderALight();
  const double size = 0.5;
  const RadiosityMesh mesh = meshWithDiscontinuities(scene, size, nullptr);
  const std::vector<uint32_t> patchOf = groupIntoShootingPatches(scene, mesh, size);
  ASSERT_EQ(patchOf.size(), mesh.elements.size());
  const uint32_t patches = *std::max_element(patchOf.begin(), patchOf.end()) + 1;
  std::vector<int> surface(patches, -2), material(patches, -1);
  std::vector<std::vector<Vec3>> centroids(patches);
  uint32_t next = 0;
  for (size_t e = 0; e < mesh.elements.size(); ++e) {
    const uint32_t p = patchOf[e];
    ASSERT_LE(p, next) << "patches are numbered in order of their first element";
    if (p == next) {
      ++next;
      surface[p] = mesh.elements[e].surface;
      material[p] = mesh.elements[e].material;
    }
    EXPECT_EQ(mesh.elements[e].surface, surface[p]);
    EXPECT_EQ(mesh.elements[e].material, material[p]);
    centroids[p].push_back(centroid(mesh.cornerPositions(e)));
  }
  // Centroids of one cell are within its diagonal of each other (cells here are 0.4 to 0.5).
  for (const auto& points : centroids)
    for (const Vec3& a : points)
      for (const Vec3& b : points) EXPECT_LE(glm::distance(a, b), size * std::sqrt(2.0) * (1 + 1e-9));
  // What a uniform mesh of 0.5 has: the floor 8 x 8, the light 2 x 2, the cube's faces 2 x 2.
  std::printf("%zu discontinuity-mesh elements in %u shooting patches\n", mesh.elements.size(), patches);
  EXPECT_EQ(patches, 64u + 4u + 6u * 4u);
  EXPECT_GT(mesh.elements.size(), 4 * size_t(patches));
}

TEST(ShootingPatchesTest, GroupedShootersSolveLikeOneShooterPerElement) {
  // The same discontinuity mesh solved twice: every triangle a patch, and triangles grouped
  // into patches of 0.5. The receivers (the nodes) are the same, so the radiosities must
  // agree up to the coarser shooters' discretisation (the energy leaving one patch is spread
  // as its mean), which is small next to B.
  const Scene scene = cubeUnderALight();
  const RadiosityMesh mesh = meshWithDiscontinuities(scene, 0.5, nullptr);
  auto solve = [&](double shooterSize) {
    SolverSettings settings;
    settings.shooterSize = shooterSize;
    settings.stopUnshotFraction = 0.001;
    ProgressiveRefinement solver(scene, mesh, settings);
    while (solver.step()) {
    }
    return std::make_pair(solver.solution(false), solver.progress());
  };
  const auto [fine, fineProgress] = solve(0.0);
  const auto [grouped, groupedProgress] = solve(0.5);
  EXPECT_LT(groupedProgress.patches * 4, fineProgress.patches);
  double worst = 0.0, meanError = 0.0, meanB = 0.0;
  for (size_t i = 0; i < fine.nodes.size(); ++i) {
    const double a = fine.nodes[i].B.g, b = grouped.nodes[i].B.g;
    worst = std::max(worst, std::abs(a - b));
    meanError += std::abs(a - b) / fine.nodes.size();
    meanB += a / fine.nodes.size();
  }
  std::printf("patches %zu -> %zu, shots %zu -> %zu; |B difference| mean %.3g, max %.3g (mean B %.3g)\n",
              fineProgress.patches, groupedProgress.patches, fineProgress.shots, groupedProgress.shots, meanError,
              worst, meanB);
  EXPECT_LT(meanError, 0.01 * meanB);
  EXPECT_LT(worst, 0.05 * meanB);
}

TEST(ShootingPatchesTest, SizeMustBePositive) {
  const RadiosityMesh mesh = meshUniformly(cubeUnderALight(), 1.0);
  EXPECT_THROW(groupIntoShootingPatches(cubeUnderALight(), mesh, 0.0), Error);
  EXPECT_THROW(groupIntoShootingPatches(cubeUnderALight(), mesh, std::nan("")), Error);
}

}  // namespace
}  // namespace radview
