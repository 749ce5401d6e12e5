#include "interp/bezier_triangle.h"

#include "core/error.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace radview {

namespace {

// The vertex opposite the longest edge, and that edge's squared length.
std::pair<int, double> longestEdgeApex(const std::array<Vec3, 3>& V) {
  int apex = 0;
  double longest2 = -1.0;
  for (int i = 0; i < 3; ++i) {
    const Vec3 e = V[(i + 2) % 3] - V[(i + 1) % 3];
    if (glm::dot(e, e) > longest2) {
      apex = i;
      longest2 = glm::dot(e, e);
    }
  }
  return {apex, longest2};
}

}  // namespace

BarycentricFrame barycentricFrame(const std::array<Vec3, 3>& V) {
  BarycentricFrame frame;
  frame.V = V;
  const auto [apex, longest2] = longestEdgeApex(V);
  const Vec3 N = glm::cross(V[(apex + 1) % 3] - V[apex], V[(apex + 2) % 3] - V[apex]);
  const double N2 = glm::dot(N, N);
  const double threshold = 16.0 * std::numeric_limits<double>::epsilon() * longest2;
  frame.degenerate = !(N2 > threshold * threshold);
  if (frame.degenerate) return frame;
  for (int i = 0; i < 3; ++i) frame.grad[i] = glm::cross(N, V[(i + 2) % 3] - V[(i + 1) % 3]) / N2;
  return frame;
}

Vec3 BarycentricFrame::operator()(const Vec3& x) const {
  if (degenerate) {
    // Linear along the longest edge A -> B, the third vertex (between them, or coincident)
    // gets nothing.
    const auto [apex, longest2] = longestEdgeApex(V);
    if (!(longest2 > 0.0)) return Vec3(1.0 / 3.0);
    const int a = (apex + 1) % 3, b = (apex + 2) % 3;
    const double t = std::clamp(glm::dot(x - V[a], V[b] - V[a]) / longest2, 0.0, 1.0);
    Vec3 lambda(0.0);
    lambda[a] = 1.0 - t;
    lambda[b] = t;
    return lambda;
  }
  // lambda_i vanishes on the edge V[i+1] V[i+2]; measured from the nearer of the two, it is
  // exactly 0 at both, so every vertex gets exactly its unit coordinates (and a dim node its
  // own value, however bright its neighbours).
  auto coordinate = [&](int i) {
    const Vec3& a = V[(i + 1) % 3];
    const Vec3& b = V[(i + 2) % 3];
    const Vec3 from = glm::dot(x - a, x - a) <= glm::dot(x - b, x - b) ? a : b;
    return glm::dot(grad[i], x - from);
  };
  const Vec3 lambda(coordinate(0), coordinate(1), coordinate(2));
  // The sum is 1 up to round-off; dividing makes the coordinates affine to the last bit, so a
  // polynomial patch (homogeneous in lambda) is not scaled by (sum)^n.
  return lambda / (lambda.x + lambda.y + lambda.z);
}

namespace {

// C&W eq. 9.7 by de Casteljau: n - 1 rounds of b^(m-1)_ijk = bu b^m_(i+1)jk + bv b^m_i(j+1)k +
// bw b^m_ij(k+1) leave the degree-1 net a_100, a_010, a_001; then B = beta . a and
// dB/dbeta_i = n a_i (the derivative of a Bernstein polynomial is n times the difference net,
// and the remaining rounds commute with taking it).
// Unrolled for each degree, between two nets that are never cleared (each round writes every
// value the next one reads).
template <int n>
BezierJet deCasteljau(const Rgb* b, const Vec3& beta) {
  std::array<Rgb, 10> nets[2];
  const Rgb* net = b;
  int into = 0;
  for (int m = n; m > 1; --m, into ^= 1) {
    Rgb* next = nets[into].data();
    for (int i = m - 1; i >= 0; --i)
      for (int j = m - 1 - i; j >= 0; --j)
        next[bezierIndex(m - 1, i, j)] = beta.x * net[bezierIndex(m, i + 1, j)] +
                                         beta.y * net[bezierIndex(m, i, j + 1)] + beta.z * net[bezierIndex(m, i, j)];
    net = next;
  }
  BezierJet jet;
  jet.B = beta.x * net[0] + beta.y * net[1] + beta.z * net[2];
  for (int i = 0; i < 3; ++i) jet.dBeta[i] = double(n) * net[i];
  return jet;
}

}  // namespace

BezierJet evaluateBezier(int n, const Rgb* b, const Vec3& beta) {
  RADVIEW_CHECK(n >= 1 && n <= 3);
  return n == 3 ? deCasteljau<3>(b, beta) : n == 2 ? deCasteljau<2>(b, beta) : deCasteljau<1>(b, beta);
}

Sample toWorld(const BezierJet& jet, const std::array<Vec3, 3>& gradBeta) {
  Sample s;
  s.B = jet.B;
  for (int c = 0; c < 3; ++c)
    s.gradient[c] = jet.dBeta[0][c] * gradBeta[0] + jet.dBeta[1][c] * gradBeta[1] + jet.dBeta[2][c] * gradBeta[2];
  return s;
}

}  // namespace radview
