#include "core/image_difference.h"

#include "core/display_transform.h"
#include "core/error.h"

#include <cmath>

namespace radview {

namespace {

bool coveredAndFinite(const float* p) {
  return p[3] > 0.0f && std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

}  // namespace

DisplayDifference displayDifference(const LinearImage& render, const ReferenceImage& reference, double exposureScale) {
  const LinearImage& other = reference.pixels;
  if (render.width != other.width || render.height != other.height)
    throw Error(reference.path, "the reference is " + std::to_string(other.width) + "x" + std::to_string(other.height) +
                                    ", the render " + std::to_string(render.width) + "x" +
                                    std::to_string(render.height) + ": render at the reference's size");
  DisplayDifference d;
  double sum = 0.0, sumSquares = 0.0;
  for (size_t i = 0; i < size_t(render.width) * render.height; ++i) {
    const float* a = &render.rgba[4 * i];
    const float* b = &other.rgba[4 * i];
    if (!coveredAndFinite(a) || !coveredAndFinite(b)) continue;
    const Rgb shownB = reference.linear ? displayed(Rgb(b[0], b[1], b[2]), exposureScale) : Rgb(b[0], b[1], b[2]);
    const double delta = luminance(displayed(Rgb(a[0], a[1], a[2]), exposureScale)) - luminance(shownB);
    ++d.pixels;
    sum += delta;
    sumSquares += delta * delta;
    d.maxAbs = std::max(d.maxAbs, std::abs(delta));
  }
  if (d.pixels > 0) {
    d.meanSigned = sum / double(d.pixels);
    d.rmse = std::sqrt(sumSquares / double(d.pixels));
  }
  return d;
}

std::ostream& operator<<(std::ostream& os, const DisplayDifference& d) {
  const auto precision = os.precision(3);
  os << d.pixels << " pixels: RMSE " << d.rmse * 255.0 << ", max " << d.maxAbs * 255.0 << ", mean "
     << d.meanSigned * 255.0 << " (8-bit steps of displayed luminance)";
  os.precision(precision);
  return os;
}

}  // namespace radview
