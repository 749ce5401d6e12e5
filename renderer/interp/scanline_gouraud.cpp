#include "interp/scanline_gouraud.h"

#include "core/error.h"

#include <algorithm>

namespace radview {

std::optional<Rgb> scanlineGouraud(const std::vector<Vec2>& polygon, const std::vector<Rgb>& values,
                                   const Vec2& p) {
  RADVIEW_CHECK(polygon.size() == values.size());
  struct Crossing {
    double x;
    Rgb value;
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
    crossings.push_back({polygon[lo].x + t * (polygon[hi].x - polygon[lo].x),
                         values[lo] + t * (values[hi] - values[lo])});
  }
  std::sort(crossings.begin(), crossings.end(), [](const Crossing& a, const Crossing& b) { return a.x < b.x; });
  for (size_t k = 0; k + 1 < crossings.size(); k += 2) {
    const Crossing& left = crossings[k];
    const Crossing& right = crossings[k + 1];
    if (p.x < left.x || p.x > right.x) continue;
    const double width = right.x - left.x;
    const double t = width > 0.0 ? (p.x - left.x) / width : 0.5;  // across the span
    return left.value + t * (right.value - left.value);
  }
  return std::nullopt;
}

}  // namespace radview
