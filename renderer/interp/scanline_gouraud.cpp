#include "interp/scanline_gouraud.h"

#include "core/error.h"

#include <algorithm>

namespace radview {

std::optional<ScanlineSample> scanlineGouraud(const std::vector<Vec2>& polygon, const std::vector<Rgb>& values,
                                              const Vec2& p) {
  RADVIEW_CHECK(polygon.size() == values.size());
  // Where an edge crosses the scanline, and how that crossing moves with the scanline.
  struct Crossing {
    double x, dxdy;
    Rgb value, dBdy;
  };
  std::vector<Crossing> crossings;
  const size_t n = polygon.size();
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    // Orient the edge upwards; horizontal edges never cross a scanline.
    size_t lo = i, hi = j;
    if (polygon[lo].y > polygon[hi].y) std::swap(lo, hi);
    const double y0 = polygon[lo].y, y1 = polygon[hi].y;
    if (!(y0 <= p.y && p.y < y1)) continue;
    const double t = (p.y - y0) / (y1 - y0);  // down the edge
    const double dx = polygon[hi].x - polygon[lo].x;
    const Rgb dB = values[hi] - values[lo];
    crossings.push_back({polygon[lo].x + t * dx, dx / (y1 - y0), values[lo] + t * dB, dB / (y1 - y0)});
  }
  std::sort(crossings.begin(), crossings.end(), [](const Crossing& a, const Crossing& b) { return a.x < b.x; });
  for (size_t k = 0; k + 1 < crossings.size(); k += 2) {
    const Crossing& left = crossings[k];
    const Crossing& right = crossings[k + 1];
    if (p.x < left.x || p.x > right.x) continue;
    const double width = right.x - left.x;
    const double s = width > 0.0 ? (p.x - left.x) / width : 0.5;  // across the span
    // d s / d y: both ends of the span move with the scanline.
    const double dsdy = width > 0.0 ? (-left.dxdy - s * (right.dxdy - left.dxdy)) / width : 0.0;
    ScanlineSample sample;
    sample.B = left.value + s * (right.value - left.value);
    for (int c = 0; c < 3; ++c) {
      const double across = right.value[c] - left.value[c];
      sample.gradient[c] = {width > 0.0 ? across / width : 0.0,
                            left.dBdy[c] + s * (right.dBdy[c] - left.dBdy[c]) + across * dsdy};
    }
    return sample;
  }
  return std::nullopt;
}

}  // namespace radview
