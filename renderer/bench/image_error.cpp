#include "bench/image_error.h"

#include "core/display_transform.h"
#include "core/error.h"

#include <algorithm>
#include <cmath>

namespace radview {

std::vector<char> interiorPixels(const RadiosityMesh& mesh, const std::vector<int32_t>& elementAt, int width,
                                 int height) {
  RADVIEW_CHECK(elementAt.size() == size_t(width) * size_t(height));
  const double tolerance = 1e-9 * mesh.bounds().diagonal();
  auto samePlane = [&](int32_t a, int32_t b) {
    if (a < 0 || b < 0) return false;
    if (a == b) return true;
    const Vec3 n = mesh.elementNormal(size_t(a));
    return glm::dot(n, mesh.elementNormal(size_t(b))) > 1.0 - 1e-9 &&
           std::abs(glm::dot(n, mesh.nodes[mesh.elements[b].corners[0]].position -
                                    mesh.nodes[mesh.elements[a].corners[0]].position)) < tolerance;
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

LuminanceError luminanceError(const LinearImage& image, const LinearImage& reference) {
  RADVIEW_CHECK(image.width == reference.width && image.height == reference.height &&
                image.rgba.size() == reference.rgba.size());
  LuminanceError error;
  double sum = 0.0;
  for (size_t i = 0; i < image.rgba.size(); i += 4) {
    const float* a = &image.rgba[i];
    const float* b = &reference.rgba[i];
    if (!(a[3] > 0.5f && b[3] > 0.5f)) continue;
    const double d = luminance(Rgb(a[0], a[1], a[2])) - luminance(Rgb(b[0], b[1], b[2]));
    if (!std::isfinite(d)) continue;
    sum += d * d;
    error.max = std::max(error.max, std::abs(d));
    ++error.pixels;
  }
  error.rmse = error.pixels ? std::sqrt(sum / double(error.pixels)) : 0.0;
  return error;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace radview
