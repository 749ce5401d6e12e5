// Numerical extremes end to end on the GPU (issue 7): the closed box of tests/extreme_scenes.h
// (T-vertices, slivers of aspect 1e4 and 1e6, quads and triangles, radiosities 1e-8..1e8) at
// scales 1e-6 and 1e6 and 1e5 from the origin, seen from inside (into a corner, 0.01 degree from
// edge-on, 1e-5 from a wall), drawn with every method, per pixel, tessellated and adaptive, and
// every view. The checks cannot pass by accident:
//  - no crack: from inside a closed box every pixel must show a surface (a crack shows the
//    background); a plane of many elements must cover every pixel inside its projected outline;
//  - every linear value finite, and for the methods that interpolate convexly (flat, Gouraud,
//    scanline Gouraud, bilinear, quadratic on linear elements) inside the nodal range;
//  - the displayed 8-bit image free of garbage: the background (magenta) nowhere, and in the
//    normal view grey everywhere, to one step (the radiosities are grey);
//  - the same image at 1e5 from the origin and at other scales as at unit scale.
#include "gl/egl_context.h"
#include "gl/mesh_renderer.h"
#include "import/load_file.h"
#include "mesh/solution_file.h"
#include "mesh/topology.h"
#include "tests/extreme_scenes.h"
#include "tests/sanitizer/sanitizer_build.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

namespace radview::gl {
namespace {

using test::extremeBox;
using test::extremeCamera;
using test::extremePlacements;
using test::insideViews;
using test::Placement;

struct MethodConfig {
  std::string name;
  Method method;
  int tessellation = 0;  // 0 per pixel, 1..64 a level, kAdaptiveTessellation
  bool perspectiveCorrect = true;
  bool convex() const { return method <= Method::Quadratic; }  // stays inside the nodal range here
};

// The sanitizer build (tests/sanitizer/sanitizer_build.h) draws the tessellated settings in the
// first view of the first placement only, which exercises radview's side of every tessellated
// path under the sanitizers; the Release build draws every setting in every view and placement.
using test::kSanitizerBuild;
bool drawTessellated(size_t placement, size_t view) { return !kSanitizerBuild || (placement == 0 && view == 0); }

// Every method of C&W §9.2 as the renderer draws it: per pixel ("exact"), tessellated at level 4
// and adaptive.
std::vector<MethodConfig> everyMethod() {
  std::vector<MethodConfig> configs = {{"flat", Method::Flat},
                                       {"gouraud", Method::Gouraud},
                                       {"gouraud screen-space", Method::Gouraud, 0, false},
                                       {"scanline-gouraud", Method::ScanlineGouraud},
                                       {"bilinear", Method::Bilinear}};
  for (Method m : {Method::Quadratic, Method::C1Quadratic, Method::CloughTocher}) {
    const std::string name = methodName(m);
    configs.push_back({name + " exact", m, 0});
    configs.push_back({name + " level 4", m, 4});
    configs.push_back({name + " adaptive", m, kAdaptiveTessellation});
  }
  return configs;
}

const glm::vec3 kMagenta{1.0f, 0.0f, 1.0f};  // the background: no grey surface and no colour scale shows it

struct LinearCheck {
  size_t nonFinite = 0, uncovered = 0, outOfRange = 0;
  std::string firstUncovered;
};

// `covered(x, y)`: whether the pixel must show a surface.
template <typename MustCover>
LinearCheck checkLinear(const LinearImage& image, bool convex, MustCover mustCover) {
  LinearCheck check;
  const double lo = 1e-8 * (1 - 1e-5), hi = 1e8 * (1 + 1e-5);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float* p = &image.rgba[(size_t(y) * image.width + x) * 4];
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]) || !std::isfinite(p[3])) {
        ++check.nonFinite;
        continue;
      }
      if (p[3] == 0.0f) {
        if (mustCover(x, y)) {
          if (check.uncovered++ == 0) check.firstUncovered = std::to_string(x) + "," + std::to_string(y);
        }
        continue;
      }
      if (convex && (p[0] < lo || p[0] > hi)) ++check.outOfRange;
    }
  return check;
}

// Pixels of the displayed image that are garbage: the background where a surface must be (outside
// the colour bar's columns), or, in the normal view of grey radiosity, a colour.
template <typename MustCover>
size_t displayGarbage(const Image& image, bool grey, int barColumns, MustCover mustCover) {
  size_t garbage = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width - barColumns; ++x) {
      const uint8_t* p = &image.rgba[(size_t(y) * image.width + x) * 4];
      const bool background = p[0] == 255 && p[1] == 0 && p[2] == 255;
      // Grey to the step: a value on a rounding boundary may round one way in one channel and the
      // other way in another (seen on llvmpipe at exactly 97.5).
      const bool coloured = std::abs(p[0] - p[1]) > 1 || std::abs(p[1] - p[2]) > 1;
      if ((background && mustCover(x, y)) || (grey && !background && coloured)) {
        if (garbage++ == 0)
          std::cout << "  garbage at " << x << "," << y << ": " << int(p[0]) << " " << int(p[1]) << " " << int(p[2])
                    << "\n";
      }
    }
  return garbage;
}

void savePngOnFailure(const Image& image, const std::string& name, bool failed) {
  if (!failed) return;
  std::string file = name;
  for (char& c : file)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  const std::string path = (std::filesystem::temp_directory_path() / ("radview_extremes_" + file + ".png")).string();
  writePng(image, path);
  std::cout << "  wrote " << path << "\n";
}

class ExtremesRender : public ::testing::Test {
 protected:
  EglContext context;
  MeshRenderer renderer;
  static constexpr int width = 160, height = 120;

  RenderSettings settingsFor(const MethodConfig& config) const {
    RenderSettings settings;
    settings.method = config.method;
    settings.tessellation = config.tessellation;
    settings.perspectiveCorrect = config.perspectiveCorrect;
    settings.background = kMagenta;
    return settings;
  }

  // Renders the mesh set on the renderer from inside the box with every method; returns the
  // uncovered pixels in all, and checks everything else.
  size_t renderEveryMethodInside(const std::string& scene, const Camera& camera, bool tessellate) {
    size_t uncovered = 0;
    const auto everywhere = [](int, int) { return true; };
    for (const MethodConfig& config : everyMethod()) {
      if (config.tessellation != 0 && !tessellate) continue;
      const std::string what = scene + ", " + config.name;
      SCOPED_TRACE(what);
      renderer.render(camera, settingsFor(config), width, height);
      const LinearCheck linear = checkLinear(renderer.readLinear(), config.convex(), everywhere);
      const Image display = renderer.readDisplay();
      const size_t garbage = displayGarbage(display, true, 0, everywhere);
      EXPECT_EQ(linear.nonFinite, 0u);
      EXPECT_EQ(linear.uncovered, 0u) << "first at " << linear.firstUncovered;
      EXPECT_EQ(linear.outOfRange, 0u);
      EXPECT_EQ(garbage, 0u);
      savePngOnFailure(display, what, linear.nonFinite + linear.uncovered + linear.outOfRange + garbage > 0);
      uncovered += linear.uncovered;
      if (linear.uncovered + linear.nonFinite + linear.outOfRange + garbage > 0)
        std::cout << "  " << what << ": " << linear.uncovered << " uncovered, " << linear.nonFinite << " not finite, "
                  << linear.outOfRange << " outside the nodal range, " << garbage << " garbage in the display\n";
    }
    return uncovered;
  }
};

// The box at every placement, from every inside view, with every method: no pixel uncovered,
// nothing non-finite, nothing outside the nodal range where the method cannot leave it.
TEST_F(ExtremesRender, ClosedBoxSeenFromInsideIsWatertightAndFiniteAtEveryScale) {
  const std::vector<Placement> placements = extremePlacements();
  for (size_t p = 0; p < placements.size(); ++p) {
    const Placement& placement = placements[p];
    renderer.setMesh(extremeBox(placement));
    size_t uncovered = 0;
    const std::vector<test::NamedView> views = insideViews();
    for (size_t k = 0; k < views.size(); ++k)
      uncovered += renderEveryMethodInside(placement.name + ", " + views[k].name,
                                           extremeCamera(placement, views[k].eye, views[k].target, views[k].up),
                                           drawTessellated(p, k));
    std::cout << placement.name << ": " << uncovered << " uncovered pixels over every view and method\n";
  }
}

// The views that divide (gradient, difference) or quantise (isolines, value) at both ends of the
// dynamic range: exposures that put 1e-8 and 1e8 at mid grey, each looking into the corner it
// shows (the darkest, the brightest).
TEST_F(ExtremesRender, EveryViewAtBothEndsOfTheDynamicRangeShowsNoGarbage) {
  const Placement placement = extremePlacements()[0];
  renderer.setMesh(extremeBox(placement));
  const auto everywhere = [](int, int) { return true; };
  const double exposures[] = {std::log2(0.18 / 1e-8), 0.0, std::log2(0.18 / 1e8)};
  for (size_t e = 0; e < 3; ++e) {
    const double exposure = exposures[e];
    const Camera camera = exposure > 0 ? extremeCamera(placement, Vec3(0.75), Vec3(0.0), {0, 1, 0}, 100.0)
                                       : extremeCamera(placement, Vec3(0.25), Vec3(1.0), {0, 1, 0}, 100.0);
    renderer.render(camera, settingsFor({"gouraud", Method::Gouraud}), width, height);
    renderer.setReferenceImage(ReferenceImage{renderer.readLinear(), true, "gouraud"});
    for (const MethodConfig& config :
         {MethodConfig{"gouraud", Method::Gouraud}, MethodConfig{"clough-tocher exact", Method::CloughTocher},
          MethodConfig{"c1-quadratic adaptive", Method::C1Quadratic, kAdaptiveTessellation}})
      for (DisplayView view : {DisplayView::Normal, DisplayView::Value, DisplayView::GradientMagnitude,
                               DisplayView::Isolines, DisplayView::Difference})
        for (auto comparison : {RenderSettings::Comparison::Method, RenderSettings::Comparison::Image}) {
          if (view != DisplayView::Difference && comparison == RenderSettings::Comparison::Image) continue;
          if (config.tessellation != 0 && !drawTessellated(0, e)) continue;
          RenderSettings settings = settingsFor(config);
          settings.exposure = exposure;
          settings.view = view;
          settings.comparison = comparison;
          const std::string what = config.name + ", view " + displayViewNames()[size_t(view)] + ", exposure " +
                                   std::to_string(exposure) +
                                   (comparison == RenderSettings::Comparison::Image ? ", against an image" : "");
          SCOPED_TRACE(what);
          renderer.render(camera, settings, width, height);
          const Image display = renderer.readDisplay();
          // The value and difference views draw their colour bar over the right 16 columns.
          const int bar = view == DisplayView::Value || view == DisplayView::Difference ? 16 : 0;
          const size_t garbage = displayGarbage(display, view == DisplayView::Normal, bar, everywhere);
          EXPECT_EQ(garbage, 0u);
          EXPECT_EQ(checkLinear(renderer.readLinear(), false, everywhere).nonFinite, 0u);
          savePngOnFailure(display, what, garbage > 0);
          if (view == DisplayView::Normal) {  // each end meaningful: distinct grey levels
            std::set<uint8_t> levels;
            for (size_t i = 0; i < display.rgba.size(); i += 4) levels.insert(display.rgba[i]);
            EXPECT_GT(levels.size(), 8u);
          }
        }
  }
}

// The red channel of pixel (x, y); the largest magnitude of it among the pixel and its four
// neighbours, the scale of the values around it.
double red(const LinearImage& image, int x, int y) { return image.rgba[(size_t(y) * image.width + x) * 4]; }
double localScale(const LinearImage& image, int x, int y) {
  double scale = std::abs(red(image, x, y));
  for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}})
    if (x + dx >= 0 && x + dx < image.width && y + dy >= 0 && y + dy < image.height)
      scale = std::max(scale, std::abs(red(image, x + dx, y + dy)));
  return scale;
}

// The linear image of each placement against the unit box's, same view: camera-relative
// rendering keeps them the same picture wherever the box is, and the interpolants' pieces,
// built on the CPU, are the same at every scale (tests/interp/scale_invariance_test.cpp).
// Gouraud (continuous, so a vertex a hair off moves values by a hair), and the C1 quadratic
// and Clough-Tocher per pixel.
TEST_F(ExtremesRender, EveryPlacementShowsTheUnitBoxPicture) {
  const auto& placements = extremePlacements();
  for (const MethodConfig& config :
       {MethodConfig{"gouraud", Method::Gouraud}, MethodConfig{"c1-quadratic exact", Method::C1Quadratic},
        MethodConfig{"clough-tocher exact", Method::CloughTocher}}) {
    LinearImage unit;
    for (const Placement& placement : placements) {
      renderer.setMesh(extremeBox(placement));
      renderer.render(extremeCamera(placement, {0.3, 0.4, 0.35}, {0.9, 0.8, 0.95}), settingsFor(config), width, height);
      const LinearImage image = renderer.readLinear();
      if (unit.rgba.empty()) unit = image;
      // Difference per pixel relative to the values around it: they change by a factor of 20
      // across a cell, so a pixel whose centre moved across an element edge would differ by far
      // more than 1e-3. Not relative to the pixel's own value: Clough-Tocher overshoots this data
      // and changes sign between neighbouring pixels (-5e3 .. 1e4 on either side of 17), where
      // the rasteriser's float32 sample point, a few 1e-5 of a pixel off at another scale, moves
      // B by its slope times that (1.8 % of 17, 3e-5 of the neighbours).
      double worst = 0.0;
      size_t over = 0;
      for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
          const double relative = std::abs(red(image, x, y) - red(unit, x, y)) / localScale(unit, x, y);
          worst = std::max(worst, relative);
          if (!(relative <= 1e-3)) ++over;
        }
      std::cout << config.name << ", " << placement.name << ": worst relative difference from the unit box " << worst
                << ", " << over << " pixels over 1e-3\n";
      EXPECT_EQ(over, 0u) << config.name << ", " << placement.name;
    }
  }
}

// A tilted square of 48 x 48 cells, every other one split in four: 4,512 T-vertices on the edges
// of the cells left whole, none of them on a line the rasteriser treats exactly (the square is
// turned about all three axes). Where the square's surface lies under a pixel centre and under
// its four neighbours', the pixel must be covered; the rest of the view shows the background.
RadiosityMesh tVertexCheckerboard(const Placement& placement, const Vec3& p0, const Vec3& a, const Vec3& b) {
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"wall", Rgb(0.5), Rgb(0.0)});
  std::map<std::pair<int, int>, uint32_t> nodeAt;  // by position in 96ths of the side
  auto node = [&](int i, int j) {
    auto [it, inserted] = nodeAt.emplace(std::make_pair(i, j), uint32_t(mesh.nodes.size()));
    if (inserted) {
      const Vec3 unit = p0 + (i / 96.0) * a + (j / 96.0) * b;
      mesh.nodes.push_back({placement.place(unit), Rgb(test::extremeRadiosity(unit)), {}});
    }
    return it->second;
  };
  auto quad = [&](int i0, int j0, int size) {
    mesh.elements.push_back(
        Element{{node(i0, j0), node(i0 + size, j0), node(i0 + size, j0 + size), node(i0, j0 + size)}, {}, 0, 0});
  };
  for (int i = 0; i < 48; ++i)
    for (int j = 0; j < 48; ++j) {
      if ((i + j) % 2) {
        quad(2 * i, 2 * j, 2);
      } else {
        for (int di = 0; di < 2; ++di)
          for (int dj = 0; dj < 2; ++dj) quad(2 * i + di, 2 * j + dj, 1);
      }
    }
  return mesh;
}

TEST_F(ExtremesRender, PlaneWithTVerticesCoversEveryPixelInsideItsOutline) {
  // The square in the unit box: corner p0, sides a and b (unit, orthogonal, turned off the axes).
  const Vec3 a = glm::normalize(Vec3(0.9, 0.3, -0.2)), b = glm::normalize(glm::cross(Vec3(0.1, 0.3, 1.0), a));
  const Vec3 p0 = Vec3(0.5) - 0.4 * (a + b);
  const Vec3 n = glm::cross(a, b);
  const int size = 384;
  size_t uncovered = 0;
  for (const size_t p : {size_t(0), size_t(4)}) {
    const Placement placement = extremePlacements()[p];
    const RadiosityMesh mesh = tVertexCheckerboard(placement, p0, 0.8 * a, 0.8 * b);
    renderer.setMesh(mesh);
    size_t tVertices = MeshTopology(mesh).tVertices().size();
    EXPECT_EQ(tVertices, 4512u);
    // Oblique views from both sides, one 1 degree from edge-on.
    const Vec3 centre = p0 + 0.4 * (a + b);
    const std::vector<Vec3> eyes = {centre + 0.9 * n + 0.3 * a, centre - 0.7 * n - 0.5 * b, centre + 0.6 * (n + a + b),
                                    centre + std::tan(M_PI / 180.0) * n + 0.9 * a};
    for (size_t k = 0; k < eyes.size(); ++k) {
      const Camera camera = extremeCamera(placement, eyes[k], centre, Vec3(0, 1, 0), 70.0);
      // Whether the ray through a pixel centre meets the square (in the unit box's frame).
      const glm::dmat4 worldFromClip = glm::inverse(camera.clipFromWorld(1.0));
      auto insideSquare = [&](int x, int y) {
        const double nx = (x + 0.5) / size * 2 - 1, ny = 1 - (y + 0.5) / size * 2;
        const glm::dvec4 near = worldFromClip * glm::dvec4(nx, ny, -1, 1),
                         far = worldFromClip * glm::dvec4(nx, ny, 1, 1);
        const Vec3 from = (Vec3(near) / near.w - placement.origin) / placement.scale + Vec3(0.5);
        const Vec3 to = (Vec3(far) / far.w - placement.origin) / placement.scale + Vec3(0.5);
        const double t = glm::dot(p0 - from, n) / glm::dot(to - from, n);
        if (!(t > 0.0)) return false;
        const Vec3 hit = from + t * (to - from) - p0;
        const double u = glm::dot(hit, a) / 0.8, v = glm::dot(hit, b) / 0.8;
        return u > 0 && u < 1 && v > 0 && v < 1;
      };
      auto mustCover = [&](int x, int y) {
        return insideSquare(x, y) && insideSquare(x - 1, y) && insideSquare(x + 1, y) && insideSquare(x, y - 1) &&
               insideSquare(x, y + 1);
      };
      for (const MethodConfig& config : everyMethod()) {
        // The sanitizer build tessellates the box above, not this plane of 5,760 quads: its
        // tessellated settings take over seven minutes a view there.
        if (config.tessellation != 0 && kSanitizerBuild) continue;
        const std::string what = placement.name + ", view " + std::to_string(k) + ", " + config.name;
        SCOPED_TRACE(what);
        renderer.render(camera, settingsFor(config), size, size);
        const LinearCheck linear = checkLinear(renderer.readLinear(), config.convex(), mustCover);
        EXPECT_EQ(linear.nonFinite, 0u);
        EXPECT_EQ(linear.uncovered, 0u) << "first at " << linear.firstUncovered;
        EXPECT_EQ(linear.outOfRange, 0u);
        const Image display = renderer.readDisplay();
        const size_t garbage = displayGarbage(display, true, 0, mustCover);
        EXPECT_EQ(garbage, 0u);
        savePngOnFailure(display, what, linear.nonFinite + linear.uncovered + linear.outOfRange + garbage > 0);
        if (linear.uncovered) std::cout << "  " << what << ": " << linear.uncovered << " cracked pixels\n";
        uncovered += linear.uncovered;
      }
    }
  }
  std::cout << uncovered << " cracked pixels over every view and method\n";
}

}  // namespace
}  // namespace radview::gl
