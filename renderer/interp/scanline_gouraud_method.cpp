// Scanline Gouraud as an interpolant of the surface (C&W §9.2, fig. 9.7-9.8): the value at a
// point is what scanline hardware shows at the pixel the point projects to, so it needs the
// view. The CPU twin of shaders/polygon.frag's scanline mode, including where that falls back
// to Gouraud on the element's triangles.
#include "interp/methods.h"
#include "interp/scanline_gouraud.h"

namespace radview {

namespace {

// shaders/lib/scanline_gouraud.glsl's MAX_POLYGON_CORNERS: larger polygons are drawn as Gouraud.
constexpr size_t kMaxScanlineCorners = 32;

class ScanlineGouraud : public Interpolant {
 public:
  ScanlineGouraud(const RadiosityMesh& mesh, const ScreenView& view)
      : mesh_(mesh), view_(view), gouraud_(makeGouraud(mesh, QuadDiagonal::D02)) {}

  Sample evaluate(uint32_t element, const Vec3& x) const override {
    const Element& e = mesh_.elements[element];
    if (e.corners.size() > kMaxScanlineCorners) return gouraud_->evaluate(element, x);
    std::vector<Vec2> screen(e.corners.size());
    std::vector<Rgb> values(e.corners.size());
    for (size_t i = 0; i < e.corners.size(); ++i) {
      const Node& node = mesh_.nodes[e.corners[i]];
      const glm::dvec4 clip = view_.clipFromWorld * glm::dvec4(node.position, 1.0);
      if (!(clip.w > 0.0)) return gouraud_->evaluate(element, x);  // a corner behind the eye
      screen[i] = window(clip);
      values[i] = node.B;
    }
    // The point on the element's plane, and where it is on the screen.
    const Vec3 n = mesh_.elementNormal(element);
    const Vec3 onPlane = x - n * glm::dot(x - mesh_.nodes[e.corners[0]].position, n);
    const glm::dvec4 clip = view_.clipFromWorld * glm::dvec4(onPlane, 1.0);
    if (!(clip.w > 0.0)) return gouraud_->evaluate(element, x);
    const std::optional<ScanlineSample> s = scanlineGouraud(screen, values, window(clip));
    if (!s) return gouraud_->evaluate(element, x);  // no span covers it: the GPU draws Gouraud there
    // The surface gradient: the screen gradient pulled back through d window / d x (chain rule
    // on window = (clip.xy / clip.w / 2 + 1/2) viewport), then kept in the element's plane.
    const glm::dmat4& m = view_.clipFromWorld;
    const Vec3 dw(m[0][3], m[1][3], m[2][3]);
    const Vec3 dcx(m[0][0], m[1][0], m[2][0]), dcy(m[0][1], m[1][1], m[2][1]);
    const Vec3 jx = 0.5 * view_.viewport.x * (dcx - (clip.x / clip.w) * dw) / clip.w;
    const Vec3 jy = 0.5 * view_.viewport.y * (dcy - (clip.y / clip.w) * dw) / clip.w;
    Sample sample{s->B, {}};
    for (int c = 0; c < 3; ++c) {
      const Vec3 g = s->gradient[c].x * jx + s->gradient[c].y * jy;
      sample.gradient[c] = g - n * glm::dot(g, n);
    }
    return sample;
  }

 private:
  Vec2 window(const glm::dvec4& clip) const { return (Vec2(clip.x, clip.y) / clip.w * 0.5 + 0.5) * view_.viewport; }

  const RadiosityMesh& mesh_;
  ScreenView view_;
  std::unique_ptr<Interpolant> gouraud_;
};

}  // namespace

std::unique_ptr<Interpolant> makeScanlineGouraud(const RadiosityMesh& mesh, const ScreenView& view) {
  return std::make_unique<ScanlineGouraud>(mesh, view);
}

}  // namespace radview
