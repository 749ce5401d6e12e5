// radview render --method final-gather (C&W §9.3.1's per-pixel evaluation of eq. 9.9 over the
// solution, radview's accuracy reference for the interpolants) or --method path-trace (the true
// image, with no solution), written as the GL renders are (same camera, exposure and tone map),
// so that either's --linear-out is a --reference for --view difference of any GL method.
#include "app/commands.h"
#include "core/camera.h"
#include "core/displayed_image.h"
#include "core/error.h"
#include "gather/final_gather.h"
#include "gather/path_tracer.h"
#include "gather/traced_surfaces.h"
#include "interp/method_registry.h"
#include "scene/camera_presets.h"

#include <memory>

#include <unistd.h>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace radview {

namespace {

// The display options that only the GL renderer draws: each an error with final-gather rather
// than silently ignored. The first one given, or nothing.
std::string glOnlyOptionGiven(const DisplayOptions& d) {
  const DisplayOptions defaults;
  if (d.view != "normal") return "--view " + d.view;
  if (d.screenSpace) return "--screen-space";
  if (d.edges) return "--edges";
  if (d.discontinuities) return "--discontinuities";
  if (d.tVertices) return "--t-vertices";
  if (d.repairTVertices) return "--repair-t-vertices";
  if (d.splitLines) return "--split-lines";
  if (d.tessellationTriangles) return "--tessellation-triangles";
  if (d.surface != defaults.surface) return "--surface";
  if (d.controlNet) return "--control-net";
  if (d.tessellation != defaults.tessellation) return "--tessellation";
  if (d.tolerance != defaults.tolerance) return "--tolerance";
  if (!d.reference.empty()) return "--reference";
  return "";
}

}  // namespace

Image displayedGather(const LinearImage& linear, double exposureScale) {
  return displayedImage(linear, exposureScale, Rgb(gl::RenderSettings{}.background));
}

void checkGatherOptions(const GatherOptions& options) {
  if (options.spp < 1 || options.spp > kMaxGatherSpp)
    throw Error("--spp " + std::to_string(options.spp) + ": expected 1.." + std::to_string(kMaxGatherSpp) +
                " samples per pixel");
  if (options.emitterSamples < 1 || options.emitterSamples > kMaxEmitterSamples)
    throw Error("--emitter-samples " + std::to_string(options.emitterSamples) + ": expected 1.." +
                std::to_string(kMaxEmitterSamples));
}

namespace {

std::unique_ptr<ProgressiveImage> finalGather(const ViewedFile& viewed, const DisplayOptions& display,
                                              const GatherOptions& options, const Camera& camera, int width,
                                              int height) {
  GatherSettings settings;
  settings.interpolant = methodFromName(options.interpolant);
  settings.interpolantOptions.cloughTocher = cloughTocherVariantFromName(display.variant);
  settings.interpolantOptions.thinPlate = thinPlateSettingsFromText(display.smoothing);
  settings.seed = options.seed;
  settings.width = width;
  settings.height = height;
  settings.camera = camera;
  settings.emitterSamples = options.emitterSamples;
  return std::make_unique<FinalGather>(viewed.mesh, settings);
}

std::unique_ptr<ProgressiveImage> pathTracer(const ViewedFile& viewed, const GatherOptions& options,
                                             const Camera& camera, int width, int height) {
  PathTraceSettings settings;
  settings.seed = options.seed;
  settings.width = width;
  settings.height = height;
  settings.camera = camera;
  return std::make_unique<PathTracer>(tracedSurfaces(viewed), settings);
}

}  // namespace

void checkRayTracedOptions(const DisplayOptions& display, const GatherOptions& options) {
  const std::string glOnly = glOnlyOptionGiven(display);
  if (!glOnly.empty()) throw Error(glOnly + ": a GL display option, not available with --method " + display.method);
  checkGatherOptions(options);
}

std::unique_ptr<ProgressiveImage> rayTracedEstimate(const ViewedFile& viewed, const DisplayOptions& display,
                                                    const GatherOptions& options, int width, int height) {
  const RayTracer tracer = rayTracerFromName(display.method).value();
  checkRayTracedOptions(display, options);
  checkRayTracingRuns(viewed, "the " + rayTracerInfo(tracer).noun);
  const Camera camera = cameraFromSpec(display.camera, viewed.mesh.bounds(), viewed.file.scene.cameras);
  if (tracer == RayTracer::FinalGather) return finalGather(viewed, display, options, camera, width, height);
  return pathTracer(viewed, options, camera, width, height);
}

void renderRayTraced(const ViewedFile& viewed, const DisplayOptions& display, const GatherOptions& options, int width,
                     int height, const std::string& out, const std::string& linearOut) {
  const RayTracer tracer = rayTracerFromName(display.method).value();
  const bool gather = tracer == RayTracer::FinalGather;
  const std::string& name = rayTracerInfo(tracer).noun;
  const auto start = std::chrono::steady_clock::now();
  const std::unique_ptr<ProgressiveImage> estimate = rayTracedEstimate(viewed, display, options, width, height);
  const bool progress = isatty(fileno(stderr));
  auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  while (estimate->samplesPerPixel() < options.spp) {
    estimate->addPasses(1);
    if (progress)
      std::fprintf(stderr, "\r%s: %d/%d spp, %.1f s", name.c_str(), estimate->samplesPerPixel(), options.spp,
                   seconds());
  }
  if (progress) std::fprintf(stderr, "\n");
  const double elapsed = seconds();

  const LinearImage image = estimate->image();
  writePng(displayedGather(image, std::exp2(display.exposure)), out);
  if (!linearOut.empty()) writeLinearImage(image, linearOut);
  std::printf("%s\n", out.c_str());
  const std::string what = gather ? ", B^ " + options.interpolant : "";
  std::printf("%s: %d spp, %dx%d%s, seed %llu: %.2f s (setup included), %.3g M rays, %.3g M rays/s\n", name.c_str(),
              estimate->samplesPerPixel(), width, height, what.c_str(), static_cast<unsigned long long>(options.seed),
              elapsed, double(estimate->raysCast()) * 1e-6, double(estimate->raysCast()) * 1e-6 / elapsed);
}

}  // namespace radview
