// Which surface each pixel shows along an edge behind which a surface's hidden back side lies:
// the far edges of the short block's top face in the solved Cornell box, seen 6 degrees from
// edge-on from the file's camera, the block's sides seen from behind (culling is off) just
// behind the face's pixels there. A rasteriser shows the top face at exactly the pixels whose
// centres its projection covers (OpenGL 4.5 §14.6.1), so each column's first top-face row is
// known from the projected edge. A back side winning there shows a pixel wide and moves that
// row down by one wherever the edge passes less than a pixel above a centre: the edge's steps
// stay a line to half a pixel, so the line fit alone does not see it.
#include "core/camera.h"
#include "core/error.h"
#include "gl/egl_context.h"
#include "gl/mesh_renderer.h"
#include "import/load_file.h"
#include "interp/method_registry.h"
#include "scene/camera_presets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace radview::gl {
namespace {

constexpr int kSize = 512;
constexpr double kTopY = 0.165;  // the short block's height (assets/make_cornell_box.py)

bool onTopFace(const RadiosityMesh& mesh, const Element& element) {
  for (uint32_t n : element.corners) {
    const Vec3& p = mesh.nodes[n].position;
    if (std::abs(p.y - kTopY) > 1e-6 || p.x > 0.35) return false;  // the tall block stands at x > 0.26, 0.33 high
  }
  return true;
}

// The solution with B red on the short block's top face and blue elsewhere: a pixel's colour
// says which of the two it shows, under any interpolant. The face's nodes are its own (the sides
// meet it along discontinuity edges of order C-1, each side with nodes of its own).
RadiosityMesh topFaceCoded(const RadiosityMesh& solved, size_t& topElements) {
  RadiosityMesh coded = solved;
  coded.hasGradients = false;
  std::vector<bool> top(coded.nodes.size(), false);
  topElements = 0;
  for (const Element& element : coded.elements)
    if (onTopFace(coded, element)) {
      ++topElements;
      for (uint32_t n : element.corners) top[n] = true;
      for (uint32_t n : element.midEdge) top[n] = true;
    }
  for (const Element& element : coded.elements)
    if (!onTopFace(coded, element))
      for (uint32_t n : element.corners)
        if (top[n]) throw Error("node " + std::to_string(n) + " is shared by the top face and another surface");
  for (size_t n = 0; n < coded.nodes.size(); ++n) coded.nodes[n].B = top[n] ? Rgb(1.0, 0.0, 0.0) : Rgb(0.0, 0.0, 1.0);
  return coded;
}

struct EdgeCheck {
  int columns = 0;
  int offPixelCentres = 0;     // columns whose first top-face row is not the one the edge gives
  double lineDeviation = 0.0;  // of the first top-face rows from their least-squares line, pixels
};

// Columns across the projected edge a -> b, the top face below it in the image: per column the
// first top-face row against the first row whose centre lies below the edge.
EdgeCheck checkEdge(const LinearImage& image, const glm::dmat4& clipFromWorld, Vec3 a, Vec3 b) {
  auto pixel = [&](Vec3 p) {
    const glm::dvec4 clip = clipFromWorld * glm::dvec4(p, 1.0);
    return glm::dvec2((clip.x / clip.w + 1.0) * 0.5 * image.width, (1.0 - clip.y / clip.w) * 0.5 * image.height);
  };
  glm::dvec2 pa = pixel(a), pb = pixel(b);
  if (pa.x > pb.x) std::swap(pa, pb);
  auto top = [&](int x, int y) {
    const float* rgba = &image.rgba[4 * (size_t(y) * image.width + x)];
    return rgba[0] > 0.5f && rgba[2] < 0.5f;
  };
  EdgeCheck check;
  std::vector<glm::dvec2> found;
  // Two pixels clear of the corners, where the other edges take over.
  for (int x = int(std::ceil(pa.x)) + 2; x + 0.5 < pb.x - 2.0; ++x) {
    const double edgeY = pa.y + (pb.y - pa.y) * (x + 0.5 - pa.x) / (pb.x - pa.x);
    if (std::abs(edgeY - 0.5 - std::round(edgeY - 0.5)) < 1e-3) continue;  // a pixel centre on the edge
    const int expected = int(std::ceil(edgeY - 0.5));
    int first = expected + 4;
    for (int y = expected - 4; y < expected + 4; ++y)
      if (top(x, y)) {
        first = y;
        break;
      }
    ++check.columns;
    if (first != expected) {
      ++check.offPixelCentres;
      std::printf("  column %d: the top face from row %d, its edge at %.3f gives row %d\n", x, first, edgeY, expected);
    }
    found.push_back({x, first});
  }
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const glm::dvec2& p : found) sx += p.x, sy += p.y, sxx += p.x * p.x, sxy += p.x * p.y;
  const double n = double(found.size());
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx), intercept = (sy - slope * sx) / n;
  for (const glm::dvec2& p : found)
    check.lineDeviation = std::max(check.lineDeviation, std::abs(p.y - slope * p.x - intercept));
  return check;
}

TEST(EdgeVisibilityTest, ShortBlockTopFaceEndsAtItsProjectedFarEdges) {
  const LoadedFile file = loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/cornell_box_solved.glb");
  size_t topElements = 0;
  const RadiosityMesh coded = topFaceCoded(file.mesh, topElements);
  ASSERT_GT(topElements, 10u);
  const Camera camera = cameraFromSpec("", coded.bounds(), file.scene.cameras);
  const glm::dmat4 clipFromWorld = camera.clipFromWorld(1.0);
  // The top face's far corners (make_cornell_box.py, mm): (290, 114) and (240, 272) on the edge
  // shared with one side, (240, 272) and (82, 225) with another; both sides are seen from behind.
  const Vec3 left{0.290, kTopY, 0.114}, far{0.240, kTopY, 0.272}, right{0.082, kTopY, 0.225};

  EglContext context;
  MeshRenderer renderer;
  renderer.setMesh(coded);
  // One method per GPU path: triangles, element polygons per pixel, C1 pieces per pixel.
  for (Method method : {Method::Gouraud, Method::ScanlineGouraud, Method::CloughTocher}) {
    SCOPED_TRACE(methodInfo(method).name);
    RenderSettings settings;
    settings.method = method;
    renderer.render(camera, settings, kSize, kSize);
    const LinearImage image = renderer.readLinear();
    for (const auto& [a, b] : {std::pair{left, far}, std::pair{far, right}}) {
      const EdgeCheck check = checkEdge(image, clipFromWorld, a, b);
      std::printf("%s: %d columns, %d off the pixel centres' row, %.2f px from a line\n",
                  methodInfo(method).name.c_str(), check.columns, check.offPixelCentres, check.lineDeviation);
      EXPECT_GT(check.columns, 25);
      EXPECT_EQ(check.offPixelCentres, 0);
      EXPECT_LT(check.lineDeviation, 0.75);
    }
  }
}

}  // namespace
}  // namespace radview::gl
