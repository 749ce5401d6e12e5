// The pixels the bench compares, and the median of its frame times.
#include "bench/image_error.h"

#include <gtest/gtest.h>

namespace radview {
namespace {

// Two elements: 0 in the plane z = 0, 1 in the plane z = 1 (parallel, apart).
RadiosityMesh twoPlanes() {
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"m", Rgb(0.5), Rgb(0.0)});
  for (double z : {0.0, 1.0})
    for (const Vec3& p : {Vec3(0, 0, z), Vec3(1, 0, z), Vec3(0, 1, z)}) mesh.nodes.push_back({p, Rgb(1.0), {}});
  mesh.elements.push_back(Element{{0, 1, 2}, {}, 0, 0});
  mesh.elements.push_back(Element{{3, 4, 5}, {}, 0, 0});
  return mesh;
}

TEST(ImageError, InteriorPixelsSeeOnePlaneWithTheirFourNeighbours) {
  // 5x4: element 0 on the left three columns, element 1 on the right two, row 3 uncovered.
  const int w = 5, h = 4;
  std::vector<int32_t> elementAt(w * h, -1);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < w; ++x) elementAt[y * w + x] = x < 3 ? 0 : 1;
  const std::vector<char> interior = interiorPixels(twoPlanes(), elementAt, w, h);
  std::string rows;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) rows += interior[y * w + x] ? '#' : '.';
    rows += '/';
  }
  // Only (1, 1) has its four neighbours on its plane: (2, 1) borders element 1, row 2 the
  // uncovered row, the rest is the border.
  EXPECT_EQ(rows, "...../.#.../...../...../");
}

TEST(ImageError, Median) {
  EXPECT_EQ(median({}), 0.0);
  EXPECT_EQ(median({3, 1, 2}), 2.0);
  EXPECT_EQ(median({4, 1, 3, 2}), 2.5);
}

}  // namespace
}  // namespace radview
