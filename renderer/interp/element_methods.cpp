// The C0 and C-1 methods that need nothing beyond the element itself: flat, Gouraud
// (barycentric on a triangulation of the element) and bilinear quads.
#include "geom/polygon.h"
#include "interp/bezier_triangle.h"
#include "interp/bilinear_map.h"
#include "interp/linear_triangle.h"
#include "interp/methods.h"
#include "mesh/display_mesh.h"

#include <limits>

namespace radview {

namespace {

class Flat : public Interpolant {
 public:
  explicit Flat(const RadiosityMesh& mesh) : mesh_(mesh) {}
  Sample evaluate(uint32_t element, const Vec3&) const override { return {mesh_.meanB(element), {}}; }

 private:
  const RadiosityMesh& mesh_;
};

// Barycentric interpolation on the triangles radview's Gouraud path draws (elementTriangles),
// so the GPU image and this reference agree triangle for triangle.
class Gouraud : public Interpolant {
 public:
  Gouraud(const RadiosityMesh& mesh, QuadDiagonal diagonal) : mesh_(mesh), triangles_(mesh.elements.size()) {
    for (size_t e = 0; e < mesh.elements.size(); ++e)
      triangles_[e] = elementTriangles(mesh, e, diagonal == QuadDiagonal::D13 ? 1 : 0);
  }

  Sample evaluate(uint32_t element, const Vec3& x) const override {
    // The piece containing x; the least-outside one for a point outside the element.
    const std::array<uint32_t, 3>* best = nullptr;
    double bestInside = -std::numeric_limits<double>::infinity();
    for (const auto& t : triangles_[element]) {
      const Vec3 w = barycentricFrame({position(t[0]), position(t[1]), position(t[2])})(x);
      const double inside = std::min(w.x, std::min(w.y, w.z));
      if (inside > bestInside) {
        bestInside = inside;
        best = &t;
      }
    }
    const auto& t = *best;
    return linearSample({position(t[0]), position(t[1]), position(t[2])},
                        {mesh_.nodes[t[0]].B, mesh_.nodes[t[1]].B, mesh_.nodes[t[2]].B}, x);
  }

 private:
  const Vec3& position(uint32_t node) const { return mesh_.nodes[node].position; }
  const RadiosityMesh& mesh_;
  std::vector<std::vector<std::array<uint32_t, 3>>> triangles_;
};

// Quads: B(s, t) bilinear in the quad's own parameters, independent of any diagonal. Other
// elements have no bilinear form and are interpolated linearly.
class Bilinear : public Interpolant {
 public:
  explicit Bilinear(const RadiosityMesh& mesh)
      : mesh_(mesh), gouraud_(mesh, QuadDiagonal::D02), convexQuad_(mesh.elements.size()) {
    // A non-convex quad folds its bilinear map (the Jacobian changes sign inside), so the
    // inverse is not unique and Newton's method can wander off (B off by 10x the data's range
    // at its own corners on a jittered grid, extremes_test). Such quads are interpolated
    // linearly.
    for (size_t e = 0; e < mesh.elements.size(); ++e)
      convexQuad_[e] = mesh.elements[e].corners.size() == 4 && isConvex(mesh.cornerPositions(e));
  }

  Sample evaluate(uint32_t element, const Vec3& x) const override {
    const Element& e = mesh_.elements[element];
    if (!convexQuad_[element]) return gouraud_.evaluate(element, x);
    std::array<Vec3, 4> p;
    std::array<Rgb, 4> f;
    for (int i = 0; i < 4; ++i) {
      p[i] = mesh_.nodes[e.corners[i]].position;
      f[i] = mesh_.nodes[e.corners[i]].B;
    }
    const BilinearMap map(p);
    const Vec2 st = map.inverse(x);
    const double s = st.x, t = st.y;
    Sample out;
    out.B = (1 - s) * (1 - t) * f[0] + s * (1 - t) * f[1] + s * t * f[2] + (1 - s) * t * f[3];
    const Rgb dfds = (1 - t) * (f[1] - f[0]) + t * (f[2] - f[3]);
    const Rgb dfdt = (1 - s) * (f[3] - f[0]) + s * (f[2] - f[1]);
    for (int c = 0; c < 3; ++c) out.gradient[c] = map.gradient(st, dfds[c], dfdt[c]);
    return out;
  }

 private:
  const RadiosityMesh& mesh_;
  Gouraud gouraud_;
  std::vector<bool> convexQuad_;
};

}  // namespace

std::unique_ptr<Interpolant> makeFlat(const RadiosityMesh& mesh) { return std::make_unique<Flat>(mesh); }
std::unique_ptr<Interpolant> makeGouraud(const RadiosityMesh& mesh, QuadDiagonal diagonal) {
  return std::make_unique<Gouraud>(mesh, diagonal);
}
std::unique_ptr<Interpolant> makeBilinear(const RadiosityMesh& mesh) { return std::make_unique<Bilinear>(mesh); }

}  // namespace radview
