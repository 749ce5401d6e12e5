#pragma once
// Small shared value types. The CPU side works in double precision (it is the numerical
// reference); the GPU gets floats.
#include <glm/glm.hpp>

#include <cmath>
#include <limits>
#include <ostream>

namespace radview {

using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;
// Linear RGB triple: radiosity B, emission E (both in the scene's radiometric unit) or
// reflectance rho (dimensionless, in [0,1]).
using Rgb = glm::dvec3;

struct Bounds {
  Vec3 lo{std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity()};

  void extend(const Vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  bool empty() const { return lo.x > hi.x; }
  Vec3 center() const { return empty() ? Vec3(0.0) : 0.5 * (lo + hi); }
  Vec3 extent() const { return empty() ? Vec3(0.0) : hi - lo; }
  double diagonal() const { return glm::length(extent()); }
};

inline bool isFinite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

inline std::ostream& operator<<(std::ostream& os, const Vec3& v) {
  return os << '(' << v.x << ", " << v.y << ", " << v.z << ')';
}
inline std::ostream& operator<<(std::ostream& os, const Bounds& b) {
  return os << '[' << b.lo << " .. " << b.hi << ']';
}

}  // namespace radview
