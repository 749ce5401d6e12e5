// The GPU's per-pixel C1 interpolants against the CPU reference (renderer/interp): every
// covered pixel of a view of assets/discontinuities.gltf (a unit square in z = 0, with C0 and
// C-1 edges) is traced back to its surface point and evaluated on the CPU.
#include "core/camera.h"
#include "gl/egl_context.h"
#include "gl/mesh_renderer.h"
#include "interp/interpolant.h"
#include "interp/surface_point.h"
#include "mesh/load_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace radview::gl {
namespace {

struct Comparison {
  size_t pixels = 0, withinTolerance = 0;
  double maxError = 0.0;
};

Comparison compare(ShadingMethod gpuMethod, Method cpuMethod, CloughTocherVariant variant, double tolerance) {
  EglContext context;
  MeshRenderer renderer;
  const RadiosityMesh mesh = loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/discontinuities.gltf").mesh;
  renderer.setMesh(mesh);
  Camera camera;
  camera.eye = {0.5, -0.6, 1.1};
  camera.target = {0.5, 0.5, 0.0};
  camera.zNear = 0.1;
  camera.zFar = 10.0;
  RenderSettings settings;
  settings.method = gpuMethod;
  settings.cloughTocher = variant;
  const int width = 120, height = 120;
  renderer.render(camera, settings, width, height);
  const LinearImage image = renderer.readLinear();

  InterpolantOptions options;
  options.cloughTocher = variant;
  const auto reference = makeInterpolant(mesh, cpuMethod, options);
  const glm::dmat4 worldFromClip = glm::inverse(camera.clipFromWorld(double(width) / height));
  Comparison result;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float* p = &image.rgba[(size_t(y) * width + x) * 4];
      if (p[3] == 0.0f) continue;
      // The pixel centre's ray, hitting the plane z = 0.
      const double nx = (x + 0.5) / width * 2 - 1, ny = 1 - (y + 0.5) / height * 2;
      const glm::dvec4 a = worldFromClip * glm::dvec4(nx, ny, -1, 1), b = worldFromClip * glm::dvec4(nx, ny, 1, 1);
      const Vec3 from = Vec3(a) / a.w, to = Vec3(b) / b.w;
      const Vec3 hit = from + (to - from) * (from.z / (from.z - to.z));
      const SurfacePoint point = nearestSurfacePoint(mesh, hit);
      const Rgb want = reference->evaluate(point.element, point.x).B;
      double error = 0.0;
      for (int c = 0; c < 3; ++c) error = std::max(error, std::abs(double(p[c]) - want[c]));
      ++result.pixels;
      if (error <= tolerance) ++result.withinTolerance;
      result.maxError = std::max(result.maxError, std::isnan(error) ? INFINITY : error);
    }
  return result;
}

// float32 control values and barycentrics: agreement to about 1e-6 of B ~ 0.5. A pixel whose
// centre lies within round-off of an element edge may be drawn by the piece on the other side
// of it than the CPU picks: across the C-1 edge that differs by the step (0.3), so a handful
// of such pixels is allowed, and nothing may be further off than the step.
void expectAgreement(ShadingMethod gpu, Method cpu, CloughTocherVariant variant) {
  const Comparison c = compare(gpu, cpu, variant, 1e-5);
  std::cout << c.pixels << " pixels, " << c.withinTolerance << " within 1e-5 of the CPU, max difference "
            << c.maxError << "\n";
  EXPECT_GT(c.pixels, 5000u);
  EXPECT_GE(c.withinTolerance, c.pixels - c.pixels / 200) << c.withinTolerance << " of " << c.pixels;
  EXPECT_LE(c.maxError, 0.31);
}

TEST(C1Gpu, CloughTocherAffinePerPixelIsTheCpuReference) {
  expectAgreement(ShadingMethod::CloughTocher, Method::CloughTocher, CloughTocherVariant::AffineInvariant);
}

TEST(C1Gpu, CloughTocherBookPerPixelIsTheCpuReference) {
  expectAgreement(ShadingMethod::CloughTocher, Method::CloughTocher, CloughTocherVariant::Book);
}

TEST(C1Gpu, PowellSabinPerPixelIsTheCpuReference) {
  expectAgreement(ShadingMethod::C1Quadratic, Method::C1Quadratic, CloughTocherVariant::AffineInvariant);
}

TEST(C1Gpu, ComparisonDiscriminates) {
  // The same check between different methods fails: it is not vacuous.
  const Comparison c = compare(ShadingMethod::Gouraud, Method::CloughTocher, CloughTocherVariant::AffineInvariant, 1e-5);
  EXPECT_LT(c.withinTolerance, c.pixels / 2);
}

}  // namespace
}  // namespace radview::gl
