#include "interp/method_registry.h"

#include "core/error.h"
#include "core/strings.h"

namespace radview {

bool drawsPieces(GpuPass pass) { return pieceDegree(pass) > 0; }

int pieceDegree(GpuPass pass) {
  switch (pass) {
    case GpuPass::Triangles:
    case GpuPass::ScanlinePolygons:
    case GpuPass::BilinearPolygons:
      return 0;
    case GpuPass::LagrangePieces:
    case GpuPass::PowellSabinPieces:
      return 2;
    case GpuPass::CloughTocherPieces:
      return 3;
  }
  return 0;
}

bool resolvesDeferred(GpuPass pass) {
  switch (pass) {
    case GpuPass::Triangles:
    case GpuPass::ScanlinePolygons:
    case GpuPass::BilinearPolygons:
    case GpuPass::LagrangePieces:  // per pixel: Lagrange triangles and serendipity quads drawn as they are
      return false;
    case GpuPass::PowellSabinPieces:
    case GpuPass::CloughTocherPieces:
      return true;
  }
  return false;
}

const std::vector<MethodInfo>& methodRegistry() {
  static const std::vector<MethodInfo> registry = {
      {Method::Flat, "flat", "", "Flat", '1', "C&W §9.2", "constant: the element's mean nodal value", false,
       GpuPass::Triangles, false},
      {Method::Gouraud, "gouraud", "linear", "Gouraud", '2', "C&W §9.2, fig. 9.7",
       "linear on each element's triangles, as the hardware interpolates (perspective-correct or in screen "
       "space)",
       false, GpuPass::Triangles, false},
      {Method::ScanlineGouraud, "scanline-gouraud", "", "Scanline Gouraud", '3', "C&W §9.2, fig. 9.7-9.8",
       "down the polygon's edges, then across each scanline, as scanline hardware did: depends on the view", true,
       GpuPass::ScanlinePolygons, false},
      {Method::Bilinear, "bilinear", "", "Bilinear", '4', "C&W §9.2, fig. 9.9",
       "quads in their bilinear parameter space, exact per pixel (orientation invariant)", false,
       GpuPass::BilinearPolygons, false},
      {Method::Quadratic, "quadratic", "", "Quadratic", '5', "C&W §9.2",
       "Lagrange on quadratic elements (mid-edge nodes), serendipity on quads: C0", false,
       GpuPass::LagrangePieces, false},
      {Method::C1Quadratic, "c1-quadratic", "", "C1 quadratic", '6', "C&W §9.2.2, fig. 9.9, 9.14b",
       "Powell-Sabin split into quadratic Bezier pieces (Reichert): C1", false, GpuPass::PowellSabinPieces, true},
      {Method::CloughTocher, "clough-tocher", "", "Clough-Tocher", '7', "C&W §9.2.2, fig. 9.14c",
       "three cubic Bezier pieces per triangle: C1, relaxed to C0 or C-1 along tagged discontinuity edges "
       "(Salesin et al. 1992)",
       false, GpuPass::CloughTocherPieces, true},
      {Method::ThinPlate, "thin-plate", "", "Thin-plate smoothed", '8', "C&W §9.2, last paragraph",
       "approximates the nodal values: a thin-plate smoothing spline per region between C-1 edges (kinks kept "
       "along C0 edges), weighted by the nodes' standard errors, then Clough-Tocher's pieces",
       false, GpuPass::CloughTocherPieces, true},
  };
  return registry;
}

const std::vector<RayTracerInfo>& rayTracerRegistry() {
  static const std::vector<RayTracerInfo> registry = {
      {RayTracer::FinalGather, "final-gather", "Final gather", "final gather", '9', "C&W §9.3.1, eq. 9.9",
       "per pixel by ray casting over the solution, --gather-method under the integral", true},
      {RayTracer::PathTrace, "path-trace", "Path traced", "path tracer", '0', "C&W eq. 2.54, the radiosity equation",
       "the true image by path tracing (no solution used): what every method converges to", false},
  };
  return registry;
}

const RayTracerInfo& rayTracerInfo(RayTracer tracer) { return rayTracerRegistry()[size_t(tracer)]; }

std::optional<RayTracer> rayTracerFromName(const std::string& name) {
  for (const RayTracerInfo& info : rayTracerRegistry())
    if (info.name == name) return info.tracer;
  return std::nullopt;
}

std::optional<RayTracer> rayTracerForKey(char key) {
  for (const RayTracerInfo& info : rayTracerRegistry())
    if (info.key == key) return info.tracer;
  return std::nullopt;
}

std::vector<std::string> pictureMethodNames() {
  std::vector<std::string> names = methodNames();
  for (const RayTracerInfo& info : rayTracerRegistry()) names.push_back(info.name);
  return names;
}

const MethodInfo& methodInfo(Method method) { return methodRegistry()[size_t(method)]; }

const std::string& methodName(Method method) { return methodInfo(method).name; }

std::vector<std::string> methodNames(bool viewIndependentOnly) {
  std::vector<std::string> names;
  for (const MethodInfo& info : methodRegistry())
    if (!viewIndependentOnly || !info.viewDependent) names.push_back(info.name);
  return names;
}

Method methodFromName(const std::string& name) {
  for (const MethodInfo& info : methodRegistry())
    if (info.name == name || (!info.alias.empty() && info.alias == name)) return info.method;
  throw Error("unknown interpolation method '" + name + "' (expected one of " + joined(methodNames()) + ")");
}

std::optional<Method> methodForKey(char key) {
  for (const MethodInfo& info : methodRegistry())
    if (info.key == key) return info.method;
  return std::nullopt;
}

}  // namespace radview
