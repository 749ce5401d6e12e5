// The one table of methods and ray tracers: what the command line, the panel and the renderers
// read from it.
#include "interp/method_registry.h"

#include "core/camera.h"
#include "core/error.h"
#include "interp/interpolant.h"
#include "scene/camera_presets.h"

#include <gtest/gtest.h>

#include <set>

namespace radview {
namespace {

TEST(MethodRegistry, EntriesAreInEnumOrderWithOneNameAndKeyEach) {
  std::set<std::string> names;
  std::set<char> keys;
  for (size_t i = 0; i < methodRegistry().size(); ++i) {
    const MethodInfo& info = methodRegistry()[i];
    EXPECT_EQ(size_t(info.method), i) << info.name;
    EXPECT_TRUE(names.insert(info.name).second) << "name used twice: " << info.name;
    if (!info.alias.empty()) {
      EXPECT_TRUE(names.insert(info.alias).second) << "alias used twice: " << info.alias;
    }
    EXPECT_TRUE(keys.insert(info.key).second) << "key used twice: " << info.key;
    EXPECT_EQ(methodForKey(info.key), info.method) << info.name;
    EXPECT_FALSE(info.label.empty() || info.summary.empty() || info.section.empty()) << info.name;
    EXPECT_EQ(rayTracerFromName(info.name), std::nullopt) << info.name;
  }
  // The ray tracers share the --method names and the number keys with the methods.
  for (size_t i = 0; i < rayTracerRegistry().size(); ++i) {
    const RayTracerInfo& info = rayTracerRegistry()[i];
    EXPECT_EQ(size_t(info.tracer), i) << info.name;
    EXPECT_TRUE(names.insert(info.name).second) << "name used twice: " << info.name;
    EXPECT_TRUE(keys.insert(info.key).second) << "key used twice: " << info.key;
    EXPECT_EQ(rayTracerForKey(info.key), info.tracer) << info.name;
    EXPECT_EQ(methodForKey(info.key), std::nullopt) << info.name;
    EXPECT_EQ(rayTracerFromName(info.name), info.tracer);
    EXPECT_FALSE(info.label.empty() || info.noun.empty() || info.summary.empty() || info.section.empty()) << info.name;
  }
  EXPECT_EQ(rayTracerForKey('9'), RayTracer::FinalGather);
  EXPECT_EQ(rayTracerForKey('0'), RayTracer::PathTrace);
  EXPECT_TRUE(rayTracerInfo(RayTracer::FinalGather).needsSolution);
  EXPECT_FALSE(rayTracerInfo(RayTracer::PathTrace).needsSolution);
  // --method's names: every method's, then every ray tracer's.
  const std::vector<std::string> pictures = pictureMethodNames();
  EXPECT_EQ(pictures.size(), methodRegistry().size() + rayTracerRegistry().size());
  EXPECT_EQ(pictures[methodRegistry().size()], "final-gather");
  EXPECT_EQ(pictures.back(), "path-trace");
}

TEST(MethodRegistry, EachMethodNamesTheGpuPassThatDrawsIt) {
  for (const MethodInfo& info : methodRegistry()) {
    const int degree = pieceDegree(info.gpu);
    EXPECT_EQ(info.bezierPieces(), degree > 0) << info.name;
    EXPECT_TRUE(degree == 0 || degree == 2 || degree == 3) << info.name;
    // The C1 methods are the ones the deferred resolve draws per pixel: their pieces' nets.
    EXPECT_EQ(resolvesDeferred(info.gpu), info.c1) << info.name;
    // A view-dependent method is drawn per pixel from its polygon, where the view is known.
    if (info.viewDependent) {
      EXPECT_EQ(info.gpu, GpuPass::ScanlinePolygons) << info.name;
    }
  }
  EXPECT_EQ(methodInfo(Method::Flat).gpu, GpuPass::Triangles);
  EXPECT_EQ(methodInfo(Method::Bilinear).gpu, GpuPass::BilinearPolygons);
  EXPECT_EQ(pieceDegree(methodInfo(Method::Quadratic).gpu), 2);
  EXPECT_EQ(pieceDegree(methodInfo(Method::C1Quadratic).gpu), 2);
  EXPECT_EQ(pieceDegree(methodInfo(Method::CloughTocher).gpu), 3);
}

TEST(MethodRegistry, NamesAndAliasesResolveAndUnknownNamesListTheKnownOnes) {
  for (const MethodInfo& info : methodRegistry()) {
    EXPECT_EQ(methodFromName(info.name), info.method);
    EXPECT_EQ(methodName(info.method), info.name);
  }
  EXPECT_EQ(methodFromName("linear"), Method::Gouraud) << "the CPU's older name";
  try {
    methodFromName("phong");
    ADD_FAILURE() << "phong was accepted";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "unknown interpolation method 'phong' (expected one of flat, gouraud, scanline-gouraud, "
                 "bilinear, quadratic, c1-quadratic, clough-tocher, thin-plate)");
  }
  const std::vector<std::string> independent = methodNames(true);
  EXPECT_EQ(independent.size(), methodRegistry().size() - 1);
  EXPECT_EQ(std::count(independent.begin(), independent.end(), "scanline-gouraud"), 0);
}

TEST(MethodRegistry, EveryMethodHasACpuInterpolantAndViewDependentOnesNeedAView) {
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"m", Rgb(0.5), Rgb(0.0)});
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)})
    mesh.nodes.push_back({p, Rgb(p.x + 2 * p.y), {}});
  mesh.elements.push_back(Element{{0, 1, 2, 3}, {}, 0, 0});
  const Camera camera = cameraFromSpec("front", mesh.bounds(), {});
  InterpolantOptions withView;
  withView.view = ScreenView{camera.clipFromWorld(1.0), Vec2(64.0)};
  for (const MethodInfo& info : methodRegistry()) {
    if (info.method == Method::Quadratic) continue;  // needs quadratic elements
    EXPECT_NEAR(makeInterpolant(mesh, info.method, withView)->evaluate(0, Vec3(0.5, 0.5, 0)).B.r, 1.5, 1e-9)
        << info.name << ": every method reproduces the centre of linear data on a square";
    if (info.viewDependent) {
      EXPECT_THROW(makeInterpolant(mesh, info.method), Error) << info.name;
    }
  }
}

}  // namespace
}  // namespace radview
