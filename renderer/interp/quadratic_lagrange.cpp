// Quadratic Lagrange elements (vertex and mid-edge nodes), C0 across element edges: the
// 6-node triangle, and the 8-node serendipity quad in the quad's bilinear parameters. Linear
// elements, and quadratic polygons of other shapes, are interpolated linearly.
#include "geom/polygon.h"
#include "interp/bezier_triangle.h"
#include "interp/bilinear_map.h"
#include "interp/methods.h"

namespace radview {

namespace {

class QuadraticLagrange : public Interpolant {
 public:
  explicit QuadraticLagrange(const RadiosityMesh& mesh)
      : mesh_(mesh), linear_(makeGouraud(mesh, QuadDiagonal::D02)), serendipity_(mesh.elements.size()) {
    for (size_t e = 0; e < mesh.elements.size(); ++e) serendipity_[e] = isSerendipityQuad(mesh, e);
  }

  Sample evaluate(uint32_t element, const Vec3& x) const override {
    const Element& e = mesh_.elements[element];
    if (isQuadraticTriangle(e)) return triangle(e, x);
    if (serendipity_[element]) return quad(e, x);
    return linear_->evaluate(element, x);
  }

 private:
  const Node& node(uint32_t i) const { return mesh_.nodes[i]; }

  // N_i = l_i (2 l_i - 1) at corners, N_ij = 4 l_i l_j at mid-edges.
  Sample triangle(const Element& e, const Vec3& x) const {
    const std::array<Vec3, 3> p = {node(e.corners[0]).position, node(e.corners[1]).position,
                                   node(e.corners[2]).position};
    const BarycentricFrame frame = barycentricFrame(p);
    const Vec3 l = frame(x);
    const std::array<Vec3, 3>& dl = frame.grad;
    Sample s;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      const Rgb& fc = node(e.corners[i]).B;
      const Rgb& fm = node(e.midEdge[i]).B;  // on edge i -> j
      s.B += l[i] * (2 * l[i] - 1) * fc + 4 * l[i] * l[j] * fm;
      const Vec3 dCorner = (4 * l[i] - 1) * dl[i];
      const Vec3 dMid = 4.0 * (l[j] * dl[i] + l[i] * dl[j]);
      for (int c = 0; c < 3; ++c) s.gradient[c] += fc[c] * dCorner + fm[c] * dMid;
    }
    return s;
  }

  // Serendipity shape functions on (xi, eta) in [-1,1]^2, corners at (+-1, +-1) counter-
  // clockwise from (-1,-1), mid-edge node i between corners i and i+1.
  Sample quad(const Element& e, const Vec3& x) const {
    std::array<Vec3, 4> p;
    for (int i = 0; i < 4; ++i) p[i] = node(e.corners[i]).position;
    const BilinearMap map(p);
    const Vec2 st = map.inverse(x);
    const double xi = 2 * st.x - 1, eta = 2 * st.y - 1;
    static const double cornerXi[4] = {-1, 1, 1, -1}, cornerEta[4] = {-1, -1, 1, 1};
    Rgb B(0.0), dxi(0.0), deta(0.0);
    for (int i = 0; i < 4; ++i) {
      const double a = cornerXi[i], b = cornerEta[i];
      const Rgb& f = node(e.corners[i]).B;
      B += 0.25 * (1 + xi * a) * (1 + eta * b) * (xi * a + eta * b - 1) * f;
      dxi += 0.25 * a * (1 + eta * b) * (2 * xi * a + eta * b) * f;
      deta += 0.25 * b * (1 + xi * a) * (xi * a + 2 * eta * b) * f;
    }
    const Rgb& m0 = node(e.midEdge[0]).B;  // eta = -1
    const Rgb& m1 = node(e.midEdge[1]).B;  // xi = +1
    const Rgb& m2 = node(e.midEdge[2]).B;  // eta = +1
    const Rgb& m3 = node(e.midEdge[3]).B;  // xi = -1
    B += 0.5 * (1 - xi * xi) * ((1 - eta) * m0 + (1 + eta) * m2) +
         0.5 * (1 - eta * eta) * ((1 + xi) * m1 + (1 - xi) * m3);
    dxi += -xi * ((1 - eta) * m0 + (1 + eta) * m2) + 0.5 * (1 - eta * eta) * (m1 - m3);
    deta += 0.5 * (1 - xi * xi) * (m2 - m0) - eta * ((1 + xi) * m1 + (1 - xi) * m3);
    Sample s;
    s.B = B;
    for (int c = 0; c < 3; ++c) s.gradient[c] = map.gradient(st, 2 * dxi[c], 2 * deta[c]);  // d/ds = 2 d/dxi
    return s;
  }

  const RadiosityMesh& mesh_;
  std::unique_ptr<Interpolant> linear_;
  std::vector<bool> serendipity_;
};

}  // namespace

bool isSerendipityQuad(const RadiosityMesh& mesh, size_t element) {
  const Element& e = mesh.elements[element];
  return e.order() == ElementOrder::Quadratic && e.corners.size() == 4 && isConvex(mesh.cornerPositions(element));
}

bool isQuadraticTriangle(const Element& e) { return e.order() == ElementOrder::Quadratic && e.corners.size() == 3; }

std::unique_ptr<Interpolant> makeQuadraticLagrange(const RadiosityMesh& mesh) {
  return std::make_unique<QuadraticLagrange>(mesh);
}

}  // namespace radview
