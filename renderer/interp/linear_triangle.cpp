#include "interp/linear_triangle.h"

#include "interp/bezier_triangle.h"

namespace radview {

Sample linearSample(const std::array<Vec3, 3>& p, const std::array<Rgb, 3>& f, const Vec3& x) {
  const BarycentricFrame frame = barycentricFrame(p);
  const Vec3 w = frame(x);
  Sample s;
  s.B = w.x * f[0] + w.y * f[1] + w.z * f[2];
  for (int c = 0; c < 3; ++c)
    s.gradient[c] = f[0][c] * frame.grad[0] + f[1][c] * frame.grad[1] + f[2][c] * frame.grad[2];
  return s;
}

}  // namespace radview
