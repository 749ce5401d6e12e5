// Scanline Gouraud, bilinear and quadratic on the GPU: fig. 9.8's orientation dependence on
// pixel values, and agreement with the CPU reference per pixel.
#include "core/camera.h"
#include "core/error.h"
#include "gl/egl_context.h"
#include "gl/mesh_renderer.h"
#include "import/load_file.h"
#include "interp/interpolant.h"
#include "tests/gl/pixel_reference.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <vector>

namespace radview::gl {
namespace {

const std::string fig98 = std::string(RADVIEW_SOURCE_DIR) + "/assets/fig9_8_quad.gltf";

// The fig. 9.8 quad seen face on, the view turned `steps` x 45 degrees clockwise.
Camera faceOn(int steps) {
  Camera c;
  c.eye = {0, 0, 2};
  c.target = {0, 0, 0};
  c.zNear = 0.1;
  c.zFar = 10;
  roll(c, glm::radians(45.0 * steps));
  return c;
}

// The red channel at the centre of a 65x65 (odd, so a pixel centre sits on the axis) render.
float centreValue(Method method, int steps) {
  EglContext context;
  MeshRenderer renderer;
  renderer.setMesh(loadFile(fig98).mesh);
  RenderSettings settings;
  settings.method = method;
  renderer.render(faceOn(steps), settings, 65, 65);
  return renderer.readLinear().rgba[(32 * 65 + 32) * 4];
}

TEST(PolygonMethods, ScanlineGouraudChangesWithTheViewAsInFig98) {
  // Corners 0.9 0.1 0.7 0.3 (float32). Upright, the centre's scanline joins the left and
  // right edges: their mean, 0.5. Turned 45 degrees one way, the scanline through the centre
  // joins two opposite corners: (0.9 + 0.7) / 2 or (0.1 + 0.3) / 2 -- the picture changes.
  const float upright = centreValue(Method::ScanlineGouraud, 0);
  const float turned = centreValue(Method::ScanlineGouraud, 1);
  const float turnedTwice = centreValue(Method::ScanlineGouraud, 2);
  EXPECT_NEAR(upright, 0.5f, 1e-3f);
  EXPECT_TRUE(std::abs(turned - 0.8f) < 1e-3f || std::abs(turned - 0.2f) < 1e-3f) << turned;
  EXPECT_NEAR(turnedTwice, 0.5f, 1e-3f);
}

TEST(PolygonMethods, BilinearIsTheSameAtEveryOrientation) {
  for (int steps = 0; steps < 3; ++steps) EXPECT_NEAR(centreValue(Method::Bilinear, steps), 0.5f, 1e-5f) << steps;
}

// An oblique view of the quad (perspective matters), rolled so no edge lies along a scanline.
Camera obliqueCamera() {
  Camera camera;
  camera.eye = {0.3, -1.1, 0.9};
  camera.target = {0, 0, 0};
  camera.up = {0.2, 0, 1};
  camera.zNear = 0.1;
  camera.zFar = 10;
  return camera;
}
constexpr int kObliqueSize = 100;

// Per pixel against the CPU on the oblique view.
test::PixelComparison obliqueComparison(Method gpu, const RadiosityMesh& mesh, const Interpolant& cpu) {
  EglContext context;
  MeshRenderer renderer;
  renderer.setMesh(mesh);
  RenderSettings settings;
  settings.method = gpu;
  renderer.render(obliqueCamera(), settings, kObliqueSize, kObliqueSize);
  return test::compareWithReference(renderer.readLinear(), obliqueCamera(), mesh, cpu, 2e-5);  // float32 pieces
}

// `mesh` with enough triangles out of view that the draw has more vertices than the image has
// pixels: the polygon pass then reads a triangle's or quad's corners per pixel rather than per
// vertex (MeshRenderer::drawPolygons).
RadiosityMesh withVerticesBeyondPixels(const RadiosityMesh& mesh) {
  return test::withTrianglesBehind(mesh, obliqueCamera(), kObliqueSize * kObliqueSize / 3 + 1);
}

// Scanline Gouraud on the GPU is the CPU's in the same view, both ways of reading the
// corners, and it is not Gouraud on the element triangles (which differs by far more).
void expectScanlineIsTheCpuReference(const RadiosityMesh& mesh) {
  InterpolantOptions options;
  options.view = ScreenView{obliqueCamera().clipFromWorld(1.0), Vec2(kObliqueSize)};
  for (const RadiosityMesh& drawn : {mesh, withVerticesBeyondPixels(mesh)}) {
    const std::unique_ptr<Interpolant> cpu = makeInterpolant(drawn, Method::ScanlineGouraud, options);
    const test::PixelComparison c = obliqueComparison(Method::ScanlineGouraud, drawn, *cpu);
    EXPECT_GT(c.pixels, 1000u);
    EXPECT_EQ(c.withinTolerance, c.pixels);
  }
  const test::PixelComparison gouraud =
      obliqueComparison(Method::ScanlineGouraud, mesh, *makeInterpolant(mesh, Method::Gouraud));
  EXPECT_GT(gouraud.maxError, 0.01);
}

TEST(PolygonMethods, ScanlineGouraudPerPixelIsTheCpuReferenceInTheSameView) {
  // An irregular quad, every corner's value different, so spans differ from row to row.
  RadiosityMesh mesh = loadFile(fig98).mesh;
  mesh.nodes[2].position = {0.7, 0.4, 0.0};
  expectScanlineIsTheCpuReference(mesh);
}

// The shader's paths for triangles, quads (here concave: a V whose rows cross all four
// edges, two spans) and larger polygons, each corner with an unrelated value.
TEST(PolygonMethods, ScanlineGouraudOfTrianglesConcaveQuadsAndPentagonsIsTheCpuReference) {
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"m", Rgb(0.5), Rgb(0.0)});
  const std::vector<std::vector<Vec3>> polygons = {
      {{0.1, -0.5, 0}, {0.5, -0.5, 0}, {0.3, -0.05, 0}},
      {{-0.5, 0.5, 0}, {-0.25, -0.5, 0}, {0, 0.5, 0}, {-0.25, 0.0, 0}},
      {{0.1, 0.05, 0}, {0.5, 0.0, 0}, {0.55, 0.35, 0}, {0.3, 0.55, 0}, {0.05, 0.4, 0}}};
  double value = 0.1;
  for (const auto& polygon : polygons) {
    Element element{{}, {}, 0, 0};
    for (const Vec3& p : polygon) {
      value = std::fmod(value + 0.37, 1.0);
      element.corners.push_back(uint32_t(mesh.nodes.size()));
      mesh.nodes.push_back({p, Rgb(value, 1 - value, 0.5), {}});
    }
    mesh.elements.push_back(element);
  }
  expectScanlineIsTheCpuReference(mesh);
}

TEST(PolygonMethods, BilinearPerPixelIsTheCpuReference) {
  // An irregular quad, so the bilinear map is not affine.
  RadiosityMesh mesh = loadFile(fig98).mesh;
  mesh.nodes[2].position = {0.7, 0.4, 0.0};
  for (const RadiosityMesh& drawn : {mesh, withVerticesBeyondPixels(mesh)}) {
    const test::PixelComparison c =
        obliqueComparison(Method::Bilinear, drawn, *makeInterpolant(drawn, Method::Bilinear));
    EXPECT_GT(c.pixels, 1000u);
    EXPECT_EQ(c.withinTolerance, c.pixels);
  }
}

TEST(PolygonMethods, QuadraticPerPixelIsTheCpuReference) {
  // Two quadratic triangles: corners and mid-edge nodes with unrelated values.
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"m", Rgb(0.5), Rgb(0.0)});
  const Vec3 p[] = {{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0.5, 0.5, 0}, {-0.5, 0.5, 0}, {0, -0.5, 0},
                    {0.5, 0, 0},     {0, 0, 0},      {0, 0.5, 0},   {-0.5, 0, 0}};
  const double B[] = {0.2, 0.9, 0.4, 0.6, 0.1, 0.8, 0.95, 0.3, 0.5};
  for (int i = 0; i < 9; ++i) mesh.nodes.push_back({p[i], Rgb(B[i], 1 - B[i], 0.5), {}});
  mesh.elements.push_back(Element{{0, 1, 2}, {4, 5, 6}, 0, 0});
  mesh.elements.push_back(Element{{0, 2, 3}, {6, 7, 8}, 0, 0});
  const test::PixelComparison c = obliqueComparison(Method::Quadratic, mesh, *makeInterpolant(mesh, Method::Quadratic));
  EXPECT_GT(c.pixels, 1000u);
  EXPECT_EQ(c.withinTolerance, c.pixels);
}

// Nodes at `corners`, valued (b, 1 - b, 0.5) from `values`, then over the first five of them an
// irregular convex 8-node serendipity quad 0-1-2-3 and a 6-node triangle 3-2-4 beside it, each
// mid-edge node with a value unrelated to its corners'.
void addQuadraticElements(RadiosityMesh& mesh, const std::vector<Vec3>& corners, const std::vector<double>& values) {
  for (size_t i = 0; i < corners.size(); ++i)
    mesh.nodes.push_back({corners[i], Rgb(values[i], 1 - values[i], 0.5), {}});
  auto mid = [&](uint32_t a, uint32_t b, double value) {
    mesh.nodes.push_back({0.5 * (corners[a] + corners[b]), Rgb(value, 0.3, 1 - value), {}});
    return uint32_t(mesh.nodes.size() - 1);
  };
  const uint32_t m01 = mid(0, 1, 0.05), m12 = mid(1, 2, 0.95), m23 = mid(2, 3, 0.1), m30 = mid(3, 0, 0.7);
  const uint32_t m24 = mid(2, 4, 0.8), m43 = mid(4, 3, 0.15);
  mesh.elements.push_back(Element{{0, 1, 2, 3}, {m01, m12, m23, m30}, 0, 0});
  mesh.elements.push_back(Element{{3, 2, 4}, {m23, m24, m43}, 0, 0});
}

// Serendipity quads per pixel in the polygon pass, the quadratic triangle in the Bezier pass,
// both the CPU reference.
TEST(PolygonMethods, SerendipityQuadsPerPixelAreTheCpuReference) {
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"m", Rgb(0.5), Rgb(0.0)});
  addQuadraticElements(mesh, {{-0.5, -0.5, 0}, {0.45, -0.55, 0}, {0.6, 0.4, 0}, {-0.4, 0.5, 0}, {0.1, 0.9, 0}},
                       {0.2, 0.9, 0.4, 0.6, 0.35});
  ASSERT_TRUE(isSerendipityQuad(mesh, 0));
  const test::PixelComparison c = obliqueComparison(Method::Quadratic, mesh, *makeInterpolant(mesh, Method::Quadratic));
  EXPECT_GT(c.pixels, 1000u);
  EXPECT_EQ(c.withinTolerance, c.pixels);
}

// Linear elements beside quadratic ones, listed before, between and after them: per pixel the
// quadratic method draws them as Gouraud's triangles, the 6-node triangle as its piece and the
// serendipity quad in the polygon pass, and every pixel is the CPU's. The linear quad has a
// T-vertex, the serendipity quad's mid-edge node, on the edge they share.
TEST(PolygonMethods, LinearElementsBesideQuadraticOnesArePerPixelTheCpuReference) {
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"m", Rgb(0.5), Rgb(0.0)});
  addQuadraticElements(mesh,
                       {{-0.5, -0.5, 0},
                        {0.45, -0.55, 0},
                        {0.6, 0.4, 0},
                        {-0.4, 0.5, 0},
                        {0.1, 0.9, 0},
                        {-0.5, -1.1, 0},
                        {0.4, -1.2, 0},
                        {1.1, -0.2, 0}},
                       {0.2, 0.9, 0.4, 0.6, 0.35, 0.75, 0.05, 0.5});
  mesh.elements.insert(mesh.elements.begin(), Element{{5, 6, 1, 0}, {}, 0, 0});   // a linear quad below edge 0-1
  mesh.elements.insert(mesh.elements.begin() + 2, Element{{1, 7, 2}, {}, 0, 0});  // a linear triangle right of 1-2
  ASSERT_TRUE(isSerendipityQuad(mesh, 1));
  ASSERT_TRUE(isQuadraticTriangle(mesh.elements[3]));
  for (const RadiosityMesh& drawn : {mesh, withVerticesBeyondPixels(mesh)}) {
    const test::PixelComparison c =
        obliqueComparison(Method::Quadratic, drawn, *makeInterpolant(drawn, Method::Quadratic));
    EXPECT_EQ(c.withinTolerance, c.pixels);
    // Every element drawn: the coverage is Gouraud's (to a few pixels along the outlines that
    // the two cut differently).
    const size_t gouraud = obliqueComparison(Method::Gouraud, drawn, *makeInterpolant(drawn, Method::Gouraud)).pixels;
    EXPECT_NEAR(double(c.pixels), double(gouraud), 0.01 * double(gouraud));
  }
}

}  // namespace
}  // namespace radview::gl

namespace radview::gl {
namespace {

// Across the seam of assets/t_vertices.gltf at the T-vertex (0.5, 0.25): the coarse side
// interpolates its edge from (0.5, 0) and (0.5, 0.5), 0.558, where the fine side has the
// node's 0.683; repaired, both sides pass through the node.
float seamJump(bool repair) {
  EglContext context;
  MeshRenderer renderer;
  renderer.setMesh(loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/t_vertices.gltf").mesh);
  Camera camera;  // looking straight at the unit square, which fills 200 x 200 pixels
  camera.eye = {0.5, 0.5, 1.0};
  camera.target = {0.5, 0.5, 0.0};
  camera.yfov = 2.0 * std::atan(0.5);
  camera.zNear = 0.1;
  camera.zFar = 10;
  RenderSettings settings;
  settings.repairTVertices = repair;
  renderer.render(camera, settings, 200, 200);
  const LinearImage image = renderer.readLinear();
  const int row = 200 - 50;  // y = 0.25, image rows from the top
  return std::abs(image.rgba[(row * 200 + 98) * 4] - image.rgba[(row * 200 + 101) * 4]);
}

TEST(TVertexRepairOnTheGpu, GouraudJumpsAtATVertexUnlessRepaired) {
  EXPECT_GT(seamJump(false), 0.1f);
  EXPECT_LT(seamJump(true), 0.02f);
}

}  // namespace
}  // namespace radview::gl

namespace radview::gl {
namespace {

// The gradient view across the fig. 9.8 quad's diagonal 0-2, two pixels apart: Gouraud's two
// triangles have gradients of magnitude 1.0 and 0.72 (a jump, what the eye sees as a Mach
// band), bilinear's gradient is continuous there.
int gradientViewJump(Method method) {
  EglContext context;
  MeshRenderer renderer;
  renderer.setMesh(loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/fig9_8_quad.gltf").mesh);
  RenderSettings settings;
  settings.method = method;
  settings.view = DisplayView::GradientMagnitude;
  settings.gradientScale = 0.05;
  renderer.render(faceOn(0), settings, 101, 101);
  const Image image = renderer.readDisplay();
  auto at = [&](int x, int y) { return &image.rgba[(size_t(y) * 101 + x) * 4]; };
  // The diagonal runs from the bottom-left to the top-right corner, y = 100 - x in rows from
  // the top; (52, 52) and (48, 48) are 2.8 pixels either side of it, beyond the reach of the
  // central differences.
  const uint8_t* a = at(52, 52);
  const uint8_t* b = at(48, 48);
  int jump = 0;
  for (int c = 0; c < 3; ++c) jump = std::max(jump, std::abs(int(a[c]) - int(b[c])));
  return jump;
}

TEST(DisplayViews, GradientViewShowsGouraudsJumpAndNotBilinears) {
  const int gouraud = gradientViewJump(Method::Gouraud), bilinear = gradientViewJump(Method::Bilinear);
  std::cout << "gradient view across the diagonal: Gouraud " << gouraud << ", bilinear " << bilinear << " steps\n";
  EXPECT_GT(gouraud, 2 * bilinear);  // measured 39 against 14
}

TEST(DisplayViews, ValueViewDrawsItsColourBar) {
  EglContext context;
  MeshRenderer renderer;
  renderer.setMesh(loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/fig9_8_quad.gltf").mesh);
  RenderSettings settings;
  settings.view = DisplayView::Value;
  renderer.render(faceOn(0), settings, 64, 64);
  const Image image = renderer.readDisplay();
  const uint8_t* top = &image.rgba[(0 * 64 + 62) * 4];
  const uint8_t* bottom = &image.rgba[(63 * 64 + 62) * 4];
  EXPECT_GT(top[0] + top[1] + top[2], 3 * 230);  // white at 1
  EXPECT_LT(bottom[0] + bottom[1], 2 * 40);      // dark blue at 0
  EXPECT_GT(bottom[2], bottom[0]);
}

TEST(DisplayViews, TheCKeyStepsToStandardErrorsOnlyWhereTheMeshHasThem) {
  EXPECT_EQ(nextCycledView(DisplayView::Isolines, true), DisplayView::StandardError);
  EXPECT_EQ(nextCycledView(DisplayView::StandardError, true), DisplayView::Normal);
  EXPECT_EQ(nextCycledView(DisplayView::Isolines, false), DisplayView::Normal);
  EXPECT_EQ(nextCycledView(DisplayView::Difference, false), DisplayView::Normal);
}

// The standard-error view colours how far B one standard error higher moves the displayed
// luminance: nothing where the errors are 0 (the scale's bottom, as at its colour bar's foot), the top
// where they move it past the scale; and it refuses a mesh without standard errors.
TEST(DisplayViews, StandardErrorViewShowsHowFarAnErrorMovesTheDisplay) {
  EglContext context;
  MeshRenderer renderer;
  RadiosityMesh mesh = loadFile(fig98).mesh;
  RenderSettings settings;
  settings.view = DisplayView::StandardError;
  renderer.setMesh(mesh);
  EXPECT_THROW(renderer.render(faceOn(0), settings, 64, 64), Error);
  auto centre = [&](double error) {
    mesh.hasStandardErrors = true;
    for (Node& node : mesh.nodes) node.standardError = Rgb(error);
    renderer.setMesh(mesh);
    renderer.render(faceOn(0), settings, 64, 64);
    const Image image = renderer.readDisplay();
    const uint8_t* c = &image.rgba[(32 * 64 + 32) * 4];
    const uint8_t* bar = &image.rgba[(63 * 64 + 62) * 4];
    return std::array<int, 6>{c[0], c[1], c[2], bar[0], bar[1], bar[2]};
  };
  const std::array<int, 6> none = centre(0.0), some = centre(2e-3), past = centre(10.0);
  // The scale's bottom, (0.02, 0.02, 0.25); the bar's lowest row is a hair above it.
  const int bottom[3] = {5, 5, 64};
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(none[k], bottom[k], 1) << "channel " << k;
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(none[3 + k], bottom[k], 8) << "channel " << k;
  for (int k = 0; k < 3; ++k) EXPECT_GT(past[k], 230) << "channel " << k;
  EXPECT_GT(some[0] + some[1] + some[2], none[0] + none[1] + none[2] + 20);
  EXPECT_LT(some[0] + some[1] + some[2], 3 * 230);
}

}  // namespace
}  // namespace radview::gl

namespace radview::gl {
namespace {

// The fig. 9.8 quad seen exactly edge-on: flat, it covers no pixel; as the radiosity surface
// (fig. 9.13) its values stand up out of its plane and are seen, finite.
size_t coveredEdgeOn(double surfaceHeight) {
  EglContext context;
  MeshRenderer renderer;
  renderer.setMesh(loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/fig9_8_quad.gltf").mesh);
  Camera camera;
  camera.eye = {0.0, -2.0, 0.0};
  camera.up = {0, 0, 1};
  camera.zNear = 0.1;
  camera.zFar = 10;
  RenderSettings settings;
  settings.method = Method::CloughTocher;
  settings.surfaceHeight = surfaceHeight;
  renderer.render(camera, settings, 80, 80);
  const LinearImage image = renderer.readLinear();
  size_t covered = 0;
  for (size_t i = 0; i < image.rgba.size(); i += 4) {
    for (int c = 0; c < 3; ++c) EXPECT_FALSE(std::isnan(image.rgba[i + c]));
    covered += image.rgba[i + 3] > 0.0f;
  }
  return covered;
}

TEST(RadiositySurface, RaisesTheValuesOutOfTheElementsPlane) {
  EXPECT_EQ(coveredEdgeOn(0.0), 0u);
  EXPECT_GT(coveredEdgeOn(0.25), 200u);
}

}  // namespace
}  // namespace radview::gl
