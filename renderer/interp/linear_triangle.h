#pragma once
// Linear interpolation on one triangle in 3D: barycentric weights and their gradients.
#include "interp/interpolant.h"

#include <array>

namespace radview {

// World-space gradients of the three barycentric functions (in the triangle's plane).
// Zero for a zero-area triangle.
std::array<Vec3, 3> barycentricGradients(const std::array<Vec3, 3>& p);

// B and its gradient of the linear interpolant of f over triangle p, at x.
Sample linearSample(const std::array<Vec3, 3>& p, const std::array<Rgb, 3>& f, const Vec3& x);

}  // namespace radview
