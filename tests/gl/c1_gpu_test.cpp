// The GPU's per-pixel C1 interpolants against the CPU reference (renderer/interp), on a view
// of assets/discontinuities.gltf (a unit square in z = 0, with C0 and C-1 edges).
#include "core/camera.h"
#include "gl/egl_context.h"
#include "gl/mesh_renderer.h"
#include "import/load_file.h"
#include "interp/interpolant.h"
#include "tests/gl/oblique_view.h"
#include "tests/gl/pixel_reference.h"

#include <gtest/gtest.h>

namespace radview::gl {
namespace {

constexpr int kSize = 120;

// `perVertex`: the mesh as it is, few triangles, drawn in one pass, each vertex reading its
// triangle's values; else with triangles out of view added until the draw has more vertices
// than the image has pixels, drawn deferred (DeferredPass::draw).
test::PixelComparison compare(Method gpuMethod, Method cpuMethod, CloughTocherVariant variant, double tolerance,
                              bool perVertex = true) {
  EglContext context;
  MeshRenderer renderer;
  RadiosityMesh mesh = loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/discontinuities.gltf").mesh;
  if (!perVertex) mesh = test::withTrianglesBehind(mesh, test::obliqueView(), kSize * kSize / 3 + 1);
  renderer.setMesh(mesh);
  const Camera camera = test::obliqueView();
  RenderSettings settings;
  settings.method = gpuMethod;
  settings.cloughTocher = variant;
  renderer.render(camera, settings, kSize, kSize);
  InterpolantOptions options;
  options.cloughTocher = variant;
  return test::compareWithReference(renderer.readLinear(), camera, mesh, *makeInterpolant(mesh, cpuMethod, options),
                                    tolerance);
}

// float32 control values and barycentrics: agreement to about 1e-6 of B ~ 0.5. A pixel whose
// centre lies within round-off of an element edge may be drawn by the piece on the other side
// of it than the CPU picks: across the C-1 edge that differs by the step (0.3), so a handful
// of such pixels is allowed, and nothing may be further off than the step.
void expectAgreement(Method gpu, Method cpu, CloughTocherVariant variant) {
  for (bool perVertex : {true, false}) {
    const test::PixelComparison c = compare(gpu, cpu, variant, 1e-5, perVertex);
    EXPECT_GT(c.pixels, 5000u);
    EXPECT_GE(c.withinTolerance, c.pixels - c.pixels / 200) << c.withinTolerance << " of " << c.pixels;
    EXPECT_LE(c.maxError, 0.31);
  }
}

TEST(C1Gpu, CloughTocherAffinePerPixelIsTheCpuReference) {
  expectAgreement(Method::CloughTocher, Method::CloughTocher, CloughTocherVariant::AffineInvariant);
}

TEST(C1Gpu, CloughTocherBookPerPixelIsTheCpuReference) {
  expectAgreement(Method::CloughTocher, Method::CloughTocher, CloughTocherVariant::Book);
}

TEST(C1Gpu, PowellSabinPerPixelIsTheCpuReference) {
  expectAgreement(Method::C1Quadratic, Method::C1Quadratic, CloughTocherVariant::AffineInvariant);
}

TEST(C1Gpu, ComparisonDiscriminates) {
  // The same check between different methods fails: it is not vacuous.
  const test::PixelComparison c =
      compare(Method::Gouraud, Method::CloughTocher, CloughTocherVariant::AffineInvariant, 1e-5);
  EXPECT_LT(c.withinTolerance, c.pixels / 2);
}

}  // namespace
}  // namespace radview::gl
