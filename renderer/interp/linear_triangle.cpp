#include "interp/linear_triangle.h"

#include "interp/surface_triangulation.h"

namespace radview {

std::array<Vec3, 3> barycentricGradients(const std::array<Vec3, 3>& p) {
  const Vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
  const double twiceArea2 = glm::dot(n, n);
  if (!(twiceArea2 > 0.0)) return {};
  // grad lambda_i = (n x (opposite edge)) / |n|^2, the opposite edge taken counter-clockwise.
  return {glm::cross(n, p[2] - p[1]) / twiceArea2, glm::cross(n, p[0] - p[2]) / twiceArea2,
          glm::cross(n, p[1] - p[0]) / twiceArea2};
}

Sample linearSample(const std::array<Vec3, 3>& p, const std::array<Rgb, 3>& f, const Vec3& x) {
  const Vec3 w = barycentricCoordinates(p[0], p[1], p[2], x);
  const std::array<Vec3, 3> dw = barycentricGradients(p);
  Sample s;
  s.B = w.x * f[0] + w.y * f[1] + w.z * f[2];
  for (int c = 0; c < 3; ++c) s.gradient[c] = f[0][c] * dw[0] + f[1][c] * dw[1] + f[2][c] * dw[2];
  return s;
}

}  // namespace radview
