#include "interp/bilinear_map.h"

#include <cmath>

namespace radview {

BilinearMap::BilinearMap(const std::array<Vec3, 4>& corners) : p_(corners) {}

Vec3 BilinearMap::operator()(const Vec2& st) const {
  const double s = st.x, t = st.y;
  return (1 - s) * (1 - t) * p_[0] + s * (1 - t) * p_[1] + s * t * p_[2] + (1 - s) * t * p_[3];
}

Vec3 BilinearMap::dxds(const Vec2& st) const { return (1 - st.y) * (p_[1] - p_[0]) + st.y * (p_[2] - p_[3]); }
Vec3 BilinearMap::dxdt(const Vec2& st) const { return (1 - st.x) * (p_[3] - p_[0]) + st.x * (p_[2] - p_[1]); }

Vec2 BilinearMap::inverse(const Vec3& x) const {
  Vec2 st(0.5, 0.5);
  for (int iteration = 0; iteration < 50; ++iteration) {
    const Vec3 r = (*this)(st)-x;
    const Vec3 a = dxds(st), b = dxdt(st);
    // Least-squares Newton step in the plane spanned by a and b (x may lie off the plane).
    const double aa = glm::dot(a, a), ab = glm::dot(a, b), bb = glm::dot(b, b);
    const double det = aa * bb - ab * ab;
    if (!(det > 1e-300)) break;
    const double ra = glm::dot(r, a), rb = glm::dot(r, b);
    const Vec2 step((bb * ra - ab * rb) / det, (aa * rb - ab * ra) / det);
    st -= step;
    if (!(std::abs(step.x) + std::abs(step.y) > 1e-15)) break;
  }
  return st;
}

Vec3 BilinearMap::gradient(const Vec2& st, double dfds, double dfdt) const {
  // grad f = [a b] (J^T J)^-1 (df/ds, df/dt), with a, b the columns of the Jacobian.
  const Vec3 a = dxds(st), b = dxdt(st);
  const double aa = glm::dot(a, a), ab = glm::dot(a, b), bb = glm::dot(b, b);
  const double det = aa * bb - ab * ab;
  if (!(det > 0.0)) return Vec3(0.0);
  const double cs = (bb * dfds - ab * dfdt) / det, ct = (aa * dfdt - ab * dfds) / det;
  return cs * a + ct * b;
}

}  // namespace radview
