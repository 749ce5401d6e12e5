#pragma once
// The display transform, the C++ twin of shaders/lib/tonemap.glsl: exposure (a scale of 2^stops),
// a clamp to [0, 1], the sRGB transfer function. "Display units" everywhere in radview are
// values after this transform, 1/255 being one 8-bit step.
#include "core/types.h"

#include <algorithm>
#include <cmath>

namespace radview {

inline double srgbEncode(double v) {
  v = std::clamp(v, 0.0, 1.0);
  return v < 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

// The inverse: a display value in [0, 1] (an 8-bit colour / 255) back to linear.
inline double srgbDecode(double v) {
  v = std::clamp(v, 0.0, 1.0);
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

inline Rgb displayed(const Rgb& B, double exposureScale) {
  return {srgbEncode(B.r * exposureScale), srgbEncode(B.g * exposureScale), srgbEncode(B.b * exposureScale)};
}

// Rec. 709 luminance weights, applied to displayed colour as the false-colour views do.
inline double luminance(const Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

}  // namespace radview
