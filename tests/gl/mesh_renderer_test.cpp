// The GL path against values computed on the CPU: what each pixel must show is known exactly
// from the camera and the mesh, so the tests compare the linear (pre-tone-map) read-back
// with it, per pixel.
#include "gl/mesh_renderer.h"
#include "core/camera.h"
#include "core/display_transform.h"
#include "core/error.h"
#include "gl/egl_context.h"

#include <gtest/gtest.h>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace radview::gl {
namespace {

// One triangle element with distinct nodal values.
RadiosityMesh triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"grey", Rgb(0.5), Rgb(0.0)});
  mesh.nodes = {{a, Rgb(0.9, 0.1, 0.2), {}}, {b, Rgb(0.1, 0.8, 0.3), {}}, {c, Rgb(0.2, 0.3, 0.7), {}}};
  mesh.elements.push_back(Element{{0, 1, 2}, {}, 0, 0});
  return mesh;
}

Camera cameraAt(const Vec3& eye, const Vec3& target) {
  Camera c;
  c.eye = eye;
  c.target = target;
  // Any up that is not along the view.
  if (glm::length(glm::cross(glm::normalize(target - eye), c.up)) < 1e-3) c.up = Vec3(0, 0, -1);
  c.yfov = glm::radians(50.0);
  c.zNear = 0.1;
  c.zFar = 100.0;
  return c;
}

struct PixelSample {
  Vec3 barycentric;
  bool inside;
};

Vec3 barycentric2(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
  const double d = (b.y - c.y) * (a.x - c.x) + (c.x - b.x) * (a.y - c.y);
  const double u = ((b.y - c.y) * (p.x - c.x) + (c.x - b.x) * (p.y - c.y)) / d;
  const double v = ((c.y - a.y) * (p.x - c.x) + (a.x - c.x) * (p.y - c.y)) / d;
  return {u, v, 1.0 - u - v};
}

// Pixel centre (x, y), row 0 at the top, to window coordinates with y up.
Vec2 windowCoords(int x, int y, int height) { return {x + 0.5, height - y - 0.5}; }

Vec2 project(const glm::dmat4& clipFromWorld, const Vec3& p, int width, int height) {
  const glm::dvec4 clip = clipFromWorld * glm::dvec4(p, 1.0);
  return {(clip.x / clip.w * 0.5 + 0.5) * width, (clip.y / clip.w * 0.5 + 0.5) * height};
}

// Barycentric coordinates, on the triangle itself, of the point the pixel's ray hits.
Vec3 surfaceBarycentric(const glm::dmat4& clipFromWorld, const Vec2& window, int width, int height,
                        const RadiosityMesh& mesh) {
  const glm::dmat4 worldFromClip = glm::inverse(clipFromWorld);
  const double nx = window.x / width * 2.0 - 1.0, ny = window.y / height * 2.0 - 1.0;
  glm::dvec4 nearPoint = worldFromClip * glm::dvec4(nx, ny, -1.0, 1.0);
  glm::dvec4 farPoint = worldFromClip * glm::dvec4(nx, ny, 1.0, 1.0);
  const Vec3 origin = Vec3(nearPoint) / nearPoint.w;
  const Vec3 direction = glm::normalize(Vec3(farPoint) / farPoint.w - origin);
  const Vec3 a = mesh.nodes[0].position, b = mesh.nodes[1].position, c = mesh.nodes[2].position;
  const Vec3 n = glm::cross(b - a, c - a);
  const Vec3 hit = origin + direction * (glm::dot(a - origin, n) / glm::dot(direction, n));
  const double area = glm::dot(n, n);
  return {glm::dot(glm::cross(c - b, hit - b), n) / area, glm::dot(glm::cross(a - c, hit - c), n) / area,
          glm::dot(glm::cross(b - a, hit - a), n) / area};
}

Rgb interpolate(const RadiosityMesh& mesh, const Vec3& w) {
  return w.x * mesh.nodes[0].B + w.y * mesh.nodes[1].B + w.z * mesh.nodes[2].B;
}

class MeshRendererTest : public ::testing::Test {
 protected:
  EglContext context;
  MeshRenderer renderer;
  static constexpr int width = 96, height = 72;
  // A triangle steeply inclined to the view, so perspective matters, and clipped by the sides
  // of the view (llvmpipe's `noperspective` gives NaN on clipped triangles: see mesh.vert).
  RadiosityMesh mesh = triangle({-2, -1, 0}, {2, -1, 0}, {0, -1, -12});
  Camera camera = cameraAt({0, 0.5, 2}, {0, -0.5, -3});

  // Largest difference, over pixels well inside the triangle, between the read-back and the
  // value `expected(window, screenBarycentric)` predicts.
  template <typename Expected>
  double maxError(const LinearImage& image, Expected expected, int& pixelsChecked) {
    const glm::dmat4 clipFromWorld = camera.clipFromWorld(double(width) / height);
    const Vec2 a = project(clipFromWorld, mesh.nodes[0].position, width, height);
    const Vec2 b = project(clipFromWorld, mesh.nodes[1].position, width, height);
    const Vec2 c = project(clipFromWorld, mesh.nodes[2].position, width, height);
    double worst = 0.0;
    pixelsChecked = 0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const Vec2 w = windowCoords(x, y, height);
        const Vec3 screen = barycentric2(w, a, b, c);
        if (glm::min(screen.x, glm::min(screen.y, screen.z)) < 0.02) continue;  // edges: coverage may differ
        const float* p = &image.rgba[(size_t(y) * width + x) * 4];
        const Rgb want = expected(w, screen);
        for (int ch = 0; ch < 3; ++ch) {
          const double error = std::abs(p[ch] - want[ch]);
          worst = std::isnan(error) ? INFINITY : std::max(worst, error);  // a NaN must not pass
        }
        ++pixelsChecked;
      }
    return worst;
  }

  // Renders with the element edges in magenta and counts the magenta pixels.
  size_t magentaEdgePixels() {
    RenderSettings settings;
    settings.elementEdges = true;
    settings.edgeColour = {1.0f, 0.0f, 1.0f, 1.0f};
    renderer.render(camera, settings, width, height);
    const Image image = renderer.readDisplay();
    size_t magenta = 0;
    for (size_t i = 0; i < image.rgba.size(); i += 4)
      if (image.rgba[i] == 255 && image.rgba[i + 1] == 0 && image.rgba[i + 2] == 255) ++magenta;
    return magenta;
  }
};

TEST_F(MeshRendererTest, ContextIsOpenGL45Core) {
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_GE(major * 10 + minor, 45) << context.description();
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT) << context.description();
}

TEST_F(MeshRendererTest, PerspectiveCorrectGouraudInterpolatesOnTheSurface) {
  renderer.setMesh(mesh);
  RenderSettings settings;
  renderer.render(camera, settings, width, height);
  const glm::dmat4 clipFromWorld = camera.clipFromWorld(double(width) / height);
  int checked = 0;
  const double error = maxError(
      renderer.readLinear(),
      [&](const Vec2& w, const Vec3&) {
        return interpolate(mesh, surfaceBarycentric(clipFromWorld, w, width, height, mesh));
      },
      checked);
  EXPECT_GT(checked, 500);
  EXPECT_LT(error, 2e-3);
}

TEST_F(MeshRendererTest, ScreenSpaceGouraudInterpolatesInTheImageAndDiffersFromPerspective) {
  renderer.setMesh(mesh);
  RenderSettings settings;
  settings.perspectiveCorrect = false;
  renderer.render(camera, settings, width, height);
  const LinearImage image = renderer.readLinear();
  int checked = 0;
  const double error = maxError(
      image, [&](const Vec2&, const Vec3& screen) { return interpolate(mesh, screen); }, checked);
  EXPECT_GT(checked, 500);
  EXPECT_LT(error, 2e-3);
  // The two interpolations really differ on this view (C&W §9.2, footnote 3).
  const glm::dmat4 clipFromWorld = camera.clipFromWorld(double(width) / height);
  const double difference = maxError(
      image,
      [&](const Vec2& w, const Vec3&) {
        return interpolate(mesh, surfaceBarycentric(clipFromWorld, w, width, height, mesh));
      },
      checked);
  EXPECT_GT(difference, 0.1);
}

TEST_F(MeshRendererTest, FlatShadingShowsTheElementMean) {
  renderer.setMesh(mesh);
  RenderSettings settings;
  settings.method = Method::Flat;
  renderer.render(camera, settings, width, height);
  int checked = 0;
  const Rgb mean = mesh.meanB(0);
  EXPECT_LT(maxError(
                renderer.readLinear(), [&](const Vec2&, const Vec3&) { return mean; }, checked),
            1e-6);
  EXPECT_GT(checked, 500);
}

TEST_F(MeshRendererTest, ToneMapAppliesExposureAndSrgb) {
  RadiosityMesh flat = triangle({-50, -50, -1}, {50, -50, -1}, {0, 50, -1});
  for (Node& n : flat.nodes) n.B = Rgb(0.25, 0.5, 2.0);
  renderer.setMesh(flat);
  RenderSettings settings;
  settings.exposure = 1.0;  // x2: 0.5, 1.0, 4.0 -> sRGB 188, 255, 255 (clamped)
  renderer.render(cameraAt({0, 0, 0}, {0, 0, -1}), settings, 8, 8);
  const Image image = renderer.readDisplay();
  EXPECT_NEAR(image.rgba[0], 188, 1);
  EXPECT_EQ(image.rgba[1], 255);
  EXPECT_EQ(image.rgba[2], 255);
}

TEST_F(MeshRendererTest, NegativeRadiosityIsShownBlackNeverNaN) {
  // C1 interpolants undershoot below 0 between nodes of high-dynamic-range data; the linear
  // image keeps the true (negative) value, the display clamps it to black before the sRGB
  // power function could turn it into NaN.
  RadiosityMesh flat = triangle({-50, -50, -1}, {50, -50, -1}, {0, 50, -1});
  for (Node& n : flat.nodes) n.B = Rgb(-0.5, -1e-30, -1e8);
  renderer.setMesh(flat);
  renderer.render(cameraAt({0, 0, 0}, {0, 0, -1}), RenderSettings{}, 8, 8);
  EXPECT_FLOAT_EQ(renderer.readLinear().rgba[0], -0.5f);
  const Image image = renderer.readDisplay();
  EXPECT_EQ(image.rgba[0], 0);
  EXPECT_EQ(image.rgba[1], 0);
  EXPECT_EQ(image.rgba[2], 0);
}

TEST_F(MeshRendererTest, CoverageIsMarkedInTheLinearImage) {
  renderer.setMesh(mesh);
  renderer.render(cameraAt({0, 0, 2}, {0, 0, 10}), RenderSettings{}, 16, 16);  // looking away
  const LinearImage away = renderer.readLinear();
  for (size_t i = 3; i < away.rgba.size(); i += 4) ASSERT_EQ(away.rgba[i], 0.0f);
  renderer.render(cameraAt({0, 5, -4}, {0, -1, -4}), RenderSettings{}, 16, 16);  // straight down on it
  const LinearImage covered = renderer.readLinear();
  EXPECT_EQ(covered.rgba[(8 * 16 + 8) * 4 + 3], 1.0f);
}

TEST_F(MeshRendererTest, ElementEdgesAreDrawnOverTheSurface) {
  renderer.setMesh(mesh);
  EXPECT_GT(magentaEdgePixels(), size_t(width) / 2);  // the triangle's edges, at least a pixel wide
}

TEST_F(MeshRendererTest, ElementEdgesBehindASurfaceAreHidden) {
  // The test triangle behind a much larger one that fills the view: none of its edges shows.
  RadiosityMesh scene = mesh;
  const uint32_t first = uint32_t(scene.nodes.size());
  for (const Vec3& p : {Vec3(-100, -100, 1.5), Vec3(100, -100, 1.5), Vec3(0, 100, 1.5)})
    scene.nodes.push_back({p, Rgb(0.5), {}});
  scene.elements.push_back(Element{{first, first + 1, first + 2}, {}, 0, 0});
  renderer.setMesh(scene);
  RenderSettings settings;
  settings.elementEdges = true;
  settings.edgeColour = {1.0f, 0.0f, 1.0f, 1.0f};
  renderer.render(camera, settings, width, height);
  const Image image = renderer.readDisplay();
  const LinearImage linear = renderer.readLinear();
  size_t shown = 0;
  for (size_t i = 0; i < image.rgba.size(); i += 4)
    if (image.rgba[i] == 255 && image.rgba[i + 1] == 0 && image.rgba[i + 2] == 255) {
      if (shown++ == 0)
        std::cout << "first edge pixel shown: (" << i / 4 % width << ", " << i / 4 / width << ") of " << width << "x"
                  << height << ", linear there " << linear.rgba[i] << " " << linear.rgba[i + 1] << " "
                  << linear.rgba[i + 2] << " " << linear.rgba[i + 3] << "\n";
    }
  EXPECT_EQ(shown, 0u) << "edge pixels shown through the surface in front";
}

TEST_F(MeshRendererTest, NearerThanZNearIsDrawnAndBehindTheEyeIsClipped) {
  // Depth clamping keeps surfaces nearer than zNear (0.1 here); a wall across the view 0.05 in
  // front of the eye covers it. What lies behind the eye is clipped at a hundredth of zNear
  // instead (shaders/lib/eye_plane.glsl): a wall 5e-4 in front of the eye is not drawn.
  const Camera ahead = cameraAt({0, 0, 2}, {0, 0, 0});
  auto centreAlphaWithWallAt = [&](double distance) {
    const double z = 2 - distance, s = 2 * distance;  // wider than the view there
    RadiosityMesh scene = mesh;
    const uint32_t first = uint32_t(scene.nodes.size());
    for (const Vec3& p : {Vec3(-s, -s, z), Vec3(s, -s, z), Vec3(0, s, z)}) scene.nodes.push_back({p, Rgb(0.5), {}});
    scene.elements.push_back(Element{{first, first + 1, first + 2}, {}, 0, 0});
    renderer.setMesh(scene);
    renderer.render(ahead, RenderSettings{}, width, height);
    const LinearImage image = renderer.readLinear();
    return image.rgba[(size_t(height / 2) * width + width / 2) * 4 + 3];
  };
  EXPECT_EQ(centreAlphaWithWallAt(0.05), 1.0f);
  EXPECT_EQ(centreAlphaWithWallAt(5e-4), 0.0f);
}

// An image shown in place of the mesh (the viewer's final gather): it is the linear read-back,
// row for row, and it is displayed as a render is, its coverage blended with the background as
// `radview render --method final-gather` blends it.
TEST_F(MeshRendererTest, AShownImageReplacesTheRadiosityAndBlendsByCoverage) {
  renderer.setMesh(mesh);
  LinearImage shown{width, height, std::vector<float>(size_t(width) * height * 4)};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float* p = &shown.rgba[(size_t(y) * width + x) * 4];
      p[0] = float(x) / width;
      p[1] = float(y) / height;
      p[2] = 0.25f;
      p[3] = float(x % 3) / 2.0f;  // coverage 0, 1/2, 1
    }
  renderer.setShownImage(shown);
  RenderSettings settings;
  settings.exposure = 1.0;
  renderer.render(camera, settings, width, height);
  EXPECT_EQ(renderer.readLinear().rgba, shown.rgba);
  const Image image = renderer.readDisplay();
  const Rgb background(settings.background);
  for (size_t i = 0; i < size_t(width) * height; ++i) {
    const float* p = &shown.rgba[4 * i];
    const Rgb want = double(p[3]) * displayed(Rgb(p[0], p[1], p[2]), 2.0) + (1.0 - p[3]) * background;
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(image.rgba[4 * i + size_t(c)], 255.0 * want[c], 1.0) << "pixel " << i;
  }
}

TEST_F(MeshRendererTest, AShownImageIsStretchedToTheRenderUntilCleared) {
  renderer.setMesh(mesh);
  renderer.render(camera, RenderSettings{}, width, height);
  const LinearImage meshOnly = renderer.readLinear();
  // Red, green over blue, white: its quadrants cover the render's.
  renderer.setShownImage(LinearImage{2, 2, {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 1, 1}});
  renderer.render(camera, RenderSettings{}, width, height);
  const LinearImage stretched = renderer.readLinear();
  auto at = [&](int x, int y) { return glm::vec4(glm::make_vec4(&stretched.rgba[(size_t(y) * width + x) * 4])); };
  EXPECT_EQ(at(width / 2 - 1, height / 2 - 1), glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(at(width / 2, 0), glm::vec4(0, 1, 0, 1));
  EXPECT_EQ(at(0, height - 1), glm::vec4(0, 0, 1, 1));
  EXPECT_EQ(at(width / 2, height / 2), glm::vec4(1, 1, 1, 1));
  renderer.clearShownImage();
  renderer.render(camera, RenderSettings{}, width, height);
  EXPECT_EQ(renderer.readLinear().rgba, meshOnly.rgba);
}

TEST_F(MeshRendererTest, ElementEdgesAreDrawnOverAShownImage) {
  renderer.setMesh(mesh);
  renderer.setShownImage(LinearImage{1, 1, {0.5f, 0.5f, 0.5f, 1.0f}});
  EXPECT_GT(magentaEdgePixels(), size_t(width) / 2);  // the mesh's depth still places its edges
}

TEST(ShaderProgram, BrokenShaderNamesTheFile) {
  EglContext context;
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "radview-broken-shaders";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "lines.vert") << "#version 450 core\nvoid main() { this is not glsl; }\n";
  std::ofstream(dir / "lines.frag") << "#version 450 core\nout vec4 c; void main() { c = vec4(1); }\n";
  struct ShaderDir {
    explicit ShaderDir(const std::string& d) { setenv("RADVIEW_SHADER_DIR", d.c_str(), 1); }
    ~ShaderDir() { unsetenv("RADVIEW_SHADER_DIR"); }
  } shaderDir(dir.string());
  try {
    ShaderProgram program({"lines.vert", "lines.frag"});
    ADD_FAILURE() << "a broken shader compiled";
  } catch (const Error& e) {
    const std::string what = e.what();
    // The file actually read, the problem, and on one line.
    EXPECT_EQ(what.rfind((dir / "lines.vert").string() + ": does not compile: ", 0), 0u) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace radview::gl
