#pragma once
// Linear interpolation on one triangle in 3D.
#include "interp/interpolant.h"

#include <array>

namespace radview {

// B and its gradient of the linear interpolant of f over triangle p, at x.
Sample linearSample(const std::array<Vec3, 3>& p, const std::array<Rgb, 3>& f, const Vec3& x);

}  // namespace radview
