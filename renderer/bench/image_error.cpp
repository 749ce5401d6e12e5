#include "bench/image_error.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>

namespace radview {

bool coplanarElements(const RadiosityMesh& mesh, size_t a, size_t b, double diagonal) {
  // Solution files hold positions in float32 (6e-8 relative), and a small element's normal
  // moves by that over its size: the tolerances are float's, not double's, so that the edges
  // between the elements of one face, where Mach bands are, stay in the comparison.
  const Vec3 n = mesh.elementNormal(a);
  return glm::dot(n, mesh.elementNormal(b)) > 1.0 - 5e-7 &&
         std::abs(glm::dot(n, mesh.nodes[mesh.elements[b].corners[0]].position -
                                  mesh.nodes[mesh.elements[a].corners[0]].position)) < 1e-6 * diagonal;
}

std::vector<char> interiorPixels(const RadiosityMesh& mesh, const std::vector<int32_t>& elementAt, int width,
                                 int height) {
  RADVIEW_CHECK(elementAt.size() == size_t(width) * size_t(height));
  const double diagonal = mesh.bounds().diagonal();
  auto samePlane = [&](int32_t a, int32_t b) {
    if (a < 0 || b < 0) return false;
    return a == b || coplanarElements(mesh, size_t(a), size_t(b), diagonal);
  };
  std::vector<char> interior(elementAt.size(), 0);
  for (int y = 1; y + 1 < height; ++y)
    for (int x = 1; x + 1 < width; ++x) {
      const size_t p = size_t(y) * width + x;
      interior[p] = samePlane(elementAt[p], elementAt[p - 1]) && samePlane(elementAt[p], elementAt[p + 1]) &&
                    samePlane(elementAt[p], elementAt[p - width]) && samePlane(elementAt[p], elementAt[p + width]);
    }
  return interior;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace radview
