#include "bench/error_map.h"

#include "core/display_transform.h"
#include "core/error.h"

#include <algorithm>
#include <cmath>

namespace radview {

namespace {

void checkSizes(const LinearImage& row, const LinearImage& reference) {
  RADVIEW_CHECK(row.width == reference.width && row.height == reference.height &&
                row.rgba.size() == reference.rgba.size());
}

// The twin of false_colour.frag's divergingScale: t in [-1, 1].
Rgb diverging(double t) {
  const double x = std::clamp(t, -1.0, 1.0);
  const Rgb white(1.0), blue(0.1, 0.25, 0.85), red(0.85, 0.1, 0.1);
  return x < 0.0 ? white + (blue - white) * -x : white + (red - white) * x;
}

double shown(const float* px, double exposureScale) {
  return 255.0 * luminance(displayed(Rgb(px[0], px[1], px[2]), exposureScale));
}

}  // namespace

LinearImage signedDifference(const LinearImage& row, const LinearImage& reference,
                             const std::vector<uint32_t>& pixels) {
  checkSizes(row, reference);
  LinearImage difference{row.width, row.height, std::vector<float>(row.rgba.size(), 0.0f)};
  for (uint32_t p : pixels) {
    for (size_t c = 0; c < 3; ++c) difference.rgba[4 * p + c] = row.rgba[4 * p + c] - reference.rgba[4 * p + c];
    difference.rgba[4 * size_t(p) + 3] = 1.0f;
  }
  return difference;
}

Image differenceMap(const LinearImage& row, const LinearImage& reference, const std::vector<uint32_t>& pixels,
                    double exposureScale, double scaleSteps) {
  checkSizes(row, reference);
  Image map{row.width, row.height, std::vector<uint8_t>(row.rgba.size(), 128)};
  for (size_t i = 3; i < map.rgba.size(); i += 4) map.rgba[i] = 255;
  for (uint32_t p : pixels) {
    const double d =
        shown(&row.rgba[4 * size_t(p)], exposureScale) - shown(&reference.rgba[4 * size_t(p)], exposureScale);
    const Rgb colour = diverging(std::isfinite(d) ? d / scaleSteps : 0.0);
    for (int c = 0; c < 3; ++c) map.rgba[4 * size_t(p) + size_t(c)] = uint8_t(std::lround(255.0 * colour[c]));
  }
  return map;
}

Image magnitudeMap(int width, int height, const std::vector<uint32_t>& pixels, const std::vector<double>& values,
                   double scaleSteps) {
  RADVIEW_CHECK(pixels.size() == values.size());
  Image map{width, height, std::vector<uint8_t>(size_t(width) * size_t(height) * 4, 128)};
  for (size_t i = 3; i < map.rgba.size(); i += 4) map.rgba[i] = 255;
  for (size_t i = 0; i < pixels.size(); ++i) {
    const Rgb colour = diverging(std::isfinite(values[i]) ? std::clamp(values[i] / scaleSteps, 0.0, 1.0) : 0.0);
    for (int c = 0; c < 3; ++c) map.rgba[4 * size_t(pixels[i]) + size_t(c)] = uint8_t(std::lround(255.0 * colour[c]));
  }
  return map;
}

}  // namespace radview
