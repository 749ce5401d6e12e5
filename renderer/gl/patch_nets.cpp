#include "gl/patch_nets.h"

#include "interp/bezier_triangle.h"

#include <cmath>
#include <vector>

namespace radview::gl {

namespace {

template <typename Patch>
void writeCorners(const Patch& patch, glm::vec3* corners) {
  for (int k = 0; k < 3; ++k) corners[k] = glm::vec3(patch.frame.V[k]);
}

// RGB value `i` into floats 3 i .. 3 i + 2 of the vec4s.
void pack(glm::vec4* out, size_t i, const Rgb& value) {
  for (size_t c = 0; c < 3; ++c) out[(3 * i + c) / 4][(3 * i + c) % 4] = float(value[c]);
}

// One step of de Casteljau's algorithm at x: the degree n net b becomes the degree n - 1 net
// of the blossom with x as one argument (C&W eq. 9.7; affine, so x may lie outside).
std::array<Rgb, 10> reduceDegree(int n, const std::array<Rgb, 10>& b, const Vec3& x) {
  std::array<Rgb, 10> r{};
  for (int i = n - 1; i >= 0; --i)
    for (int j = n - 1 - i; j >= 0; --j)
      r[bezierIndex(n - 1, i, j)] =
          x.x * b[bezierIndex(n, i + 1, j)] + x.y * b[bezierIndex(n, i, j + 1)] + x.z * b[bezierIndex(n, i, j)];
  return r;
}

constexpr double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

// Clough-Tocher piece k's coordinates sigma (clough_tocher.cpp's evaluatePiece) of the big
// triangle's corner m.
Vec3 pieceCoordinates(int k, int m) {
  const int k1 = (k + 1) % 3, o = (k + 2) % 3;
  const Vec3 lambda(m == 0, m == 1, m == 2);
  return {lambda[k] - lambda[o], lambda[k1] - lambda[o], 3.0 * lambda[o]};
}

// Clough-Tocher's 12 packed values (patch_nets.h) from the nets of pieces 1 and 2.
std::array<Rgb, 12> packCloughTocher(const std::array<Rgb, 10>& piece1, const std::array<Rgb, 10>& piece2) {
  std::array<Rgb, 12> packed{};
  // P, the polynomial of piece 1 (where lambda_0 is the smallest), over the whole triangle:
  // its Bezier net in lambda is its blossom at the corners, b_ijk = P[e0^i, e1^j, e2^k],
  // packed times its Bernstein weight.
  for (int i = 3; i >= 0; --i)
    for (int j = 3 - i; j >= 0; --j) {
      std::array<Rgb, 10> b = piece1;
      int n = 3;
      for (int m = 0; m < 3; ++m)
        for (int repeat = m == 0 ? i : m == 1 ? j : 3 - i - j; repeat > 0; --repeat, --n)
          b = reduceDegree(n, b, pieceCoordinates(1, m));
      const double weight = 6.0 / (factorial(i) * factorial(j) * factorial(3 - i - j));  // c1_pieces.glsl
      packed[size_t(bezierIndex(3, i, j))] = weight * b[0];
    }
  // The other pieces differ from P by alpha psi_1 + beta psi_2 (patch_nets.h); piece 2's
  // difference at the corners e1 and e0 is alpha and alpha - beta.
  const auto difference = [&](int m) {
    return evaluateBezier(piece2, pieceCoordinates(2, m)).B - evaluateBezier(piece1, pieceCoordinates(1, m)).B;
  };
  packed[10] = difference(1);
  packed[11] = packed[10] - difference(0);
  return packed;
}

// The packing is linear in the two nets, with weights that are the same in every triangle (the
// split is, in barycentric coordinates): found once from unit nets and kept as the nonzero
// terms, a few hundred multiply-adds per triangle where the blossoms take thousands.
struct PackingTerm {
  size_t packed, input;  // input: control value 0-9 of piece 1, 10-19 of piece 2
  double weight;
};

const std::vector<PackingTerm>& cloughTocherPacking() {
  static const std::vector<PackingTerm> terms = [] {
    std::vector<PackingTerm> found;
    for (size_t input = 0; input < 20; ++input) {
      std::array<Rgb, 10> piece1{}, piece2{};
      (input < 10 ? piece1[input] : piece2[input - 10]) = Rgb(1.0);
      const std::array<Rgb, 12> packed = packCloughTocher(piece1, piece2);
      for (size_t v = 0; v < packed.size(); ++v)
        if (std::abs(packed[v].x) > 1e-12) found.push_back({v, input, packed[v].x});
    }
    return found;
  }();
  return terms;
}

}  // namespace

void writeNet(const CloughTocherPatch& patch, glm::vec3* corners, glm::vec4* net) {
  writeCorners(patch, corners);
  std::array<Rgb, 12> packed{};
  for (const PackingTerm& term : cloughTocherPacking())
    packed[term.packed] +=
        term.weight * (term.input < 10 ? patch.control[1][term.input] : patch.control[2][term.input - 10]);
  // By corner (patch_nets.h).
  static constexpr size_t kByCorner[12] = {
      bezierIndex(3, 3, 0), bezierIndex(3, 1, 2), bezierIndex(3, 1, 0), bezierIndex(3, 2, 0),
      bezierIndex(3, 2, 1), bezierIndex(3, 0, 3), bezierIndex(3, 0, 1), bezierIndex(3, 1, 1),
      10,                   bezierIndex(3, 0, 2), bezierIndex(3, 0, 0), 11};
  for (size_t v = 0; v < packed.size(); ++v) pack(net, v, packed[kByCorner[v]]);
}

void writeNet(const PowellSabinPatch& patch, glm::vec3* corners, glm::vec4* net) {
  writeCorners(patch, corners);
  // Piece 2 k is (f_k, bVR_k, ...) and 2 k + 1 (f_k+1, bV1R_k, ...), b200 b110 first; bVR_k =
  // f_k + t_k D_k / 2 and bV1R_k = f_k+1 + (1 - t_k) E_k / 2 (powell_sabin.cpp), so D and E
  // come back from them exactly but for rounding, also where a degenerate triangle is linear.
  std::array<Rgb, 3> f, D, E;
  for (size_t k = 0; k < 3; ++k) {
    const auto &near = patch.control[2 * k], &far = patch.control[2 * k + 1];
    const double t = patch.t[k];
    f[k] = near[0];
    D[k] = 2.0 * (near[1] - near[0]) / t;
    E[k] = 2.0 * (far[1] - far[0]) / (1.0 - t);
  }
  // Corner k's two values of the sums (Q's Bezier net in lambda, b200 = f_0 and b110 = f_0 +
  // D_0 / 2 and so on, times its Bernstein weights), then e_k and t_k (patch_nets.h).
  const std::array<std::array<Rgb, 2>, 3> sums = {{{f[0], 2.0 * f[2] + D[2]},  //
                                                   {2.0 * f[0] + D[0], f[1]},  //
                                                   {2.0 * f[1] + D[1], f[2]}}};
  for (size_t k = 0; k < 3; ++k) {
    const size_t k1 = (k + 1) % 3;
    // Q's derivative along edge k from V_k+1 is D_k - 2 (f_k+1 - f_k): a quadratic's
    // derivatives at the ends of a segment average to its difference quotient.
    const Rgb e = E[k] - D[k] + 2.0 * (f[k1] - f[k]);
    pack(net, 4 * k, sums[k][0]);
    pack(net, 4 * k + 1, sums[k][1]);
    pack(net, 4 * k + 2, e);
    // zeta sums to 1: the first corner holds two of them beside its t, so that the one pass's
    // first vertex finds all it needs in 5 vec4 (c1_forward.vert).
    net[3 * k + 2].y = float(patch.t[k]);
    net[3 * k + 2].z = k == 0 ? float(patch.zeta[0]) : 0.0f;
    net[3 * k + 2].w = k == 0 ? float(patch.zeta[1]) : 0.0f;
  }
}

}  // namespace radview::gl
