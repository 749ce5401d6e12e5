#pragma once
// Random planes and polynomial fields for the single-triangle interpolant tests (Bezier
// triangles, Clough-Tocher, Powell-Sabin): data whose exact values and gradients are known,
// on triangles placed anywhere in 3D. (The whole-mesh tests use test::Plane, one fixed plane,
// from test_meshes.h.)
#include "core/types.h"
#include "interp/bezier_triangle.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <random>

namespace radview::test {

// A random rotation: about a random axis, by an angle in (-pi, pi).
inline glm::dmat3 randomRotation(std::mt19937& random) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Vec3 axis = glm::normalize(Vec3(u(random), u(random), u(random)) + Vec3(1e-3));
  return glm::dmat3(glm::rotate(glm::dmat4(1.0), 3.14159 * u(random), axis));
}

// A plane in 3D with an orthonormal frame: 2D coordinates (u, v) <-> points, 2D vectors <->
// vectors in the plane.
struct PlaneFrame {
  Vec3 origin, e1, e2;
  Vec3 at(const Vec2& p) const { return origin + p.x * e1 + p.y * e2; }
  Vec3 vector(const Vec2& d) const { return d.x * e1 + d.y * e2; }
};
// A randomly rotated frame with its origin in [-3, 3]^3.
inline PlaneFrame randomPlane(std::mt19937& random) {
  const glm::dmat3 R = randomRotation(random);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return {3.0 * Vec3(u(random), u(random), u(random)), R[0], R[1]};
}

// Three corners' values and in-plane gradients, every component uniform in [-1, 1], and the
// largest gradient's length.
struct RandomData {
  std::array<Rgb, 3> f;
  std::array<RgbGradient, 3> g;
  double gradientScale = 0.0;
};
inline RandomData randomData(std::mt19937& random, const PlaneFrame& plane) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  RandomData d;
  for (int i = 0; i < 3; ++i) {
    d.f[i] = Rgb(u(random), u(random), u(random));
    for (Vec3& gc : d.g[i]) {
      gc = plane.vector({u(random), u(random)});
      d.gradientScale = std::max(d.gradientScale, glm::length(gc));
    }
  }
  return d;
}

// A polynomial per channel in plane coordinates, up to cubic: q(p) = c + a.p + p^T H p / 2 +
// t (p.x^3, p.x^2 p.y, p.x p.y^2, p.y^3); t = 0 for a quadratic.
struct Polynomial {
  std::array<double, 3> c{};
  std::array<Vec2, 3> a{};
  std::array<glm::dmat2, 3> H{};
  std::array<glm::dvec4, 3> t{};
  Rgb operator()(const Vec2& p) const {
    Rgb out;
    for (int ch = 0; ch < 3; ++ch)
      out[ch] = c[ch] + glm::dot(a[ch], p) + 0.5 * glm::dot(p, H[ch] * p) +
                glm::dot(t[ch], glm::dvec4(p.x * p.x * p.x, p.x * p.x * p.y, p.x * p.y * p.y, p.y * p.y * p.y));
    return out;
  }
  // The exact gradient at p, as world-space vectors in the plane.
  RgbGradient gradient(const PlaneFrame& plane, const Vec2& p) const {
    RgbGradient g;
    for (int ch = 0; ch < 3; ++ch) {
      const glm::dvec4& k = t[ch];
      const Vec2 d = a[ch] + H[ch] * p +
                     Vec2(3 * k.x * p.x * p.x + 2 * k.y * p.x * p.y + k.z * p.y * p.y,
                          k.y * p.x * p.x + 2 * k.z * p.x * p.y + 3 * k.w * p.y * p.y);
      g[ch] = plane.vector(d);
    }
    return g;
  }
};
// Coefficients uniform in [-1, 1]; a quadratic (t = 0) unless `cubic`.
inline Polynomial randomPolynomial(std::mt19937& random, bool cubic) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Polynomial q;
  for (int ch = 0; ch < 3; ++ch) {
    q.c[ch] = u(random);
    q.a[ch] = {u(random), u(random)};
    const double off = u(random);
    q.H[ch] = glm::dmat2(u(random), off, off, u(random));
    if (cubic) q.t[ch] = {u(random), u(random), u(random), u(random)};
  }
  return q;
}

}  // namespace radview::test
