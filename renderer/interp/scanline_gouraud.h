#pragma once
// Gouraud shading as scanline hardware computed it (C&W §9.2, fig. 9.7): values are
// interpolated down the two polygon edges that span the current scanline, then across the
// span. The result depends on how the polygon lies on the screen, which is the point: it
// reproduces fig. 9.8 (one quad, three rotations, three pictures), the discontinuities
// between scanlines inside concave polygons, and the jumps at T-vertices.
#include "core/types.h"

#include <array>
#include <optional>
#include <vector>

namespace radview {

// The value at a point of a span and its derivatives in screen coordinates, per channel
// (d/dx, d/dy), within the span.
struct ScanlineSample {
  Rgb B{0.0};
  std::array<Vec2, 3> gradient{};
};

// `polygon` in screen coordinates (any units; scanlines are lines of constant y), `values`
// one per vertex. Returns the value at p, or nothing where no span covers p. Spans are taken
// between successive edge crossings sorted by x (even-odd), and a crossing counts for edges
// with y0 <= y < y1 (half-open), as a rasteriser does, so a vertex is counted once.
std::optional<ScanlineSample> scanlineGouraud(const std::vector<Vec2>& polygon, const std::vector<Rgb>& values,
                                              const Vec2& p);

}  // namespace radview
