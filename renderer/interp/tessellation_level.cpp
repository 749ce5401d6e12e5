#include "interp/tessellation_level.h"

#include "interp/bezier_triangle.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace radview {

namespace {

// Slope of the sRGB transfer function at linear value v (clamped below at 0).
double srgbSlope(double v) {
  v = std::max(v, 0.0);
  return v <= 0.0031308 ? 12.92 : (1.055 / 2.4) * std::pow(v, -7.0 / 12.0);
}

// The control value with exponents (i, j, k) of a degree-n net.
const Rgb& at(const Rgb* net, int n, int i, int j) { return net[bezierIndex(n, i, j)]; }

double largestComponent(const Rgb& v) { return std::max({std::abs(v.r), std::abs(v.g), std::abs(v.b)}); }

// The smallest L with (constant * M / L^2) * s * slope <= tolerance, in 1..64.
int levelFor(double constant, double M, double darkest, double exposureScale, double tolerance) {
  if (exposureScale * darkest >= 1.0) return 1;  // saturated white whatever the error
  const double displayError = constant * M * exposureScale * srgbSlope(exposureScale * darkest);
  const double L = std::ceil(std::sqrt(displayError / tolerance));
  return std::isfinite(L) ? int(std::clamp(L, 1.0, double(kMaxTessellationLevel))) : kMaxTessellationLevel;
}

}  // namespace

TessellationLevels adaptiveTessellationLevels(int n, const Rgb* net, double exposureScale, double tolerance) {
  TessellationLevels levels;
  if (n < 2) return levels;  // linear: exact at level 1
  const double order = n * (n - 1.0);
  double M = 0.0, darkest = INFINITY;
  std::array<double, 3> edgeM{}, edgeDarkest{INFINITY, INFINITY, INFINITY};
  for (int i = n; i >= 0; --i)
    for (int j = n - i; j >= 0; --j) {
      const int k = n - i - j;
      const Rgb& b = at(net, n, i, j);
      const double low = std::min({b.r, b.g, b.b});
      darkest = std::min(darkest, low);
      // Corner c's opposite edge holds the controls whose exponent c is 0.
      const int exponents[3] = {i, j, k};
      for (int c = 0; c < 3; ++c)
        if (exponents[c] == 0) edgeDarkest[c] = std::min(edgeDarkest[c], low);
    }
  // Second differences b_{a+2e_p} - 2 b_{a+e_p+e_q} + b_{a+2e_q} for every |a| = n-2 and pair
  // (p, q); written (x + y) - 2 m so both orders of an edge give the same bits.
  for (int i = n - 2; i >= 0; --i)
    for (int j = n - 2 - i; j >= 0; --j) {
      const int k = n - 2 - i - j;
      const Rgb& ii = at(net, n, i + 2, j);
      const Rgb& jj = at(net, n, i, j + 2);
      const Rgb& kk = at(net, n, i, j);  // k + 2 implied
      const Rgb& ij = at(net, n, i + 1, j + 1);
      const Rgb& ik = at(net, n, i + 1, j);
      const Rgb& jk = at(net, n, i, j + 1);
      const double dij = largestComponent((ii + jj) - 2.0 * ij);
      const double dik = largestComponent((ii + kk) - 2.0 * ik);
      const double djk = largestComponent((jj + kk) - 2.0 * jk);
      M = std::max({M, dij, dik, djk});
      // The pair (p, q) lies along the edge opposite the third corner when that corner's
      // exponent is 0 throughout: a = (i, j, 0) for the edge opposite corner 2, etc.
      if (k == 0) edgeM[2] = std::max(edgeM[2], dij);
      if (j == 0) edgeM[1] = std::max(edgeM[1], dik);
      if (i == 0) edgeM[0] = std::max(edgeM[0], djk);
    }
  for (int c = 0; c < 3; ++c)
    levels.outer[c] = levelFor(order / 8.0, edgeM[c], edgeDarkest[c], exposureScale, tolerance);
  levels.inner = levelFor(order / 2.0, M, darkest, exposureScale, tolerance);  // rings: see the header
  return levels;
}

std::vector<TessellationLevels> tessellationLevelsForPieces(int degree, const std::vector<std::array<Vec3, 3>>& corners,
                                                            const std::vector<const Rgb*>& nets, double exposureScale,
                                                            double tolerance) {
  std::vector<TessellationLevels> levels(nets.size());
  for (size_t p = 0; p < nets.size(); ++p)
    levels[p] = adaptiveTessellationLevels(degree, nets[p], exposureScale, tolerance);
  // Edges keyed by their corner positions rounded to float (pieces that share an edge share
  // its corners to within that), endpoints in a fixed order.
  using Key = std::array<float, 6>;
  auto keyOf = [&](size_t p, int c) {
    const glm::vec3 a(corners[p][(c + 1) % 3]), b(corners[p][(c + 2) % 3]);
    const bool ordered = std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    const glm::vec3 &lo = ordered ? a : b, &hi = ordered ? b : a;
    return Key{lo.x, lo.y, lo.z, hi.x, hi.y, hi.z};
  };
  std::map<Key, int> need;
  for (size_t p = 0; p < nets.size(); ++p)
    for (int c = 0; c < 3; ++c) {
      int& level = need[keyOf(p, c)];
      level = std::max({level, levels[p].outer[c], levels[p].inner});
    }
  for (size_t p = 0; p < nets.size(); ++p)
    for (int c = 0; c < 3; ++c) levels[p].outer[c] = need[keyOf(p, c)];
  return levels;
}

}  // namespace radview
