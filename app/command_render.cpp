#include "app/commands.h"
#include "app/solve_progress_bar.h"
#include "core/camera.h"
#include "core/error.h"
#include "core/image_difference.h"
#include "core/limits.h"
#include "core/memory_budget.h"
#include "core/strings.h"
#include "gl/egl_context.h"
#include "gl/mesh_renderer.h"
#include "interp/method_registry.h"
#include "interp/tessellation_level.h"
#include "scene/camera_presets.h"
#include "mesh/standard_errors.h"
#include "solve/viewed_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <regex>

namespace radview {

void parseSize(const std::string& text, int& width, int& height, const std::string& option) {
  std::smatch m;
  // Up to 9 digits: anything longer is past the limit anyway, and stoi cannot overflow.
  static const std::regex pattern(R"((\d{1,9})x(\d{1,9}))");
  if (!std::regex_match(text, m, pattern))
    throw Error(option + " '" + text + "': expected WIDTHxHEIGHT, e.g. 1024x768");
  width = std::stoi(m[1]);
  height = std::stoi(m[2]);
  if (width < 1 || height < 1) throw Error(option + " '" + text + "': each side must be at least 1 pixel");
  checkLimit(option + " " + text, uint64_t(std::max(width, height)), kMaxImageSide, "pixels on a side");
}

void checkImageMemory(const std::string& sizeText, int width, int height, uint64_t bytesPerPixel,
                      const std::string& what) {
  checkMemory("--size " + sizeText, what, uint64_t(width) * uint64_t(height) * bytesPerPixel);
}

gl::RenderSettings settingsFrom(const DisplayOptions& display) {
  gl::RenderSettings settings;
  settings.method = methodFromName(display.method);
  settings.perspectiveCorrect = !display.screenSpace;
  settings.exposure = display.exposure;
  settings.view = gl::displayViewFromName(display.view);
  settings.elementEdges = display.edges;
  settings.discontinuityEdges = display.discontinuities;
  settings.tVertices = display.tVertices;
  settings.repairTVertices = display.repairTVertices;
  settings.splitLines = display.splitLines;
  settings.tessellationTriangles = display.tessellationTriangles;
  if (!(display.surface >= 0.0 && display.surface <= 10.0))
    throw Error("--surface " + std::to_string(display.surface) + ": expected a height fraction 0 .. 10");
  settings.surfaceHeight = display.surface;
  if (display.controlNet && display.surface == 0.0) throw Error("--control-net needs --surface");
  settings.controlNet = display.controlNet;
  settings.cloughTocher = cloughTocherVariantFromName(display.variant);
  settings.thinPlate = thinPlateSettingsFromText(display.smoothing);
  settings.tessellation = parseTessellation(display.tessellation);
  if (!(display.tolerance >= 0.01 && display.tolerance <= 100.0))
    throw Error("--tolerance " + std::to_string(display.tolerance) + ": expected 0.01 .. 100 8-bit steps");
  settings.tessellationTolerance = display.tolerance / 255.0;
  settings.comparisonMethod = methodFromName(display.compareWith);
  settings.comparison =
      display.reference.empty() ? gl::RenderSettings::Comparison::Method : gl::RenderSettings::Comparison::Image;
  if (!display.reference.empty() && settings.view != gl::DisplayView::Difference)
    throw Error("--reference needs --view difference");
  if (!(display.differenceScale >= 0.01 && display.differenceScale <= 255.0))
    throw Error("--difference-scale " + std::to_string(display.differenceScale) + ": expected 0.01 .. 255 8-bit steps");
  settings.differenceScale = display.differenceScale / 255.0;
  return settings;
}

int parseTessellation(const std::string& text) {
  if (text == "per-pixel") return 0;
  if (text == "adaptive") return gl::kAdaptiveTessellation;
  const std::optional<int64_t> level = parseInteger(text);
  if (!level || *level < 1 || *level > kMaxTessellationLevel)
    throw Error("--tessellation '" + text + "': expected per-pixel, adaptive or a level 1.." +
                std::to_string(kMaxTessellationLevel));
  return int(*level);
}

void drawHeadless(gl::MeshRenderer& renderer, const std::shared_ptr<const ViewedFile>& shared,
                  const DisplayOptions& display, int width, int height) {
  const ViewedFile& viewed = *shared;
  const gl::RenderSettings settings = settingsFrom(display);
  if (settings.view == gl::DisplayView::StandardError && !viewed.mesh.hasStandardErrors)
    throw Error(viewed.file.path, viewed.file.isSolution
                                      ? "has no standard errors to show (--view standard-error): its solver did "
                                        "not estimate them"
                                      : "has no standard errors to show (--view standard-error) when drawn with "
                                        "--direct-only, which casts no rays");
  const Camera camera = cameraFromSpec(display.camera, viewed.mesh.bounds(), viewed.file.scene.cameras);
  ReferenceImage reference;
  if (!display.reference.empty()) {
    reference = readReferenceImage(display.reference);
    if (reference.pixels.width != width || reference.pixels.height != height)
      throw Error(display.reference, "the image is " + std::to_string(reference.pixels.width) + "x" +
                                         std::to_string(reference.pixels.height) + ": render it with --size " +
                                         std::to_string(reference.pixels.width) + "x" +
                                         std::to_string(reference.pixels.height));
  }
  renderer.setMesh(std::shared_ptr<const RadiosityMesh>(shared, &viewed.mesh));
  if (!display.reference.empty()) renderer.setReferenceImage(reference);
  renderer.render(camera, settings, width, height);
}

void renderHeadless(const std::shared_ptr<const ViewedFile>& shared, const DisplayOptions& display, int width,
                    int height, const std::string& out, const std::string& linearOut) {
  const ViewedFile& viewed = *shared;
  const gl::RenderSettings settings = settingsFrom(display);
  gl::EglContext context;
  gl::MeshRenderer renderer;
  drawHeadless(renderer, shared, display, width, height);
  writePng(renderer.readDisplay(), out);
  if (!linearOut.empty()) writeLinearImage(renderer.readLinear(), linearOut);
  std::printf("%s\n", out.c_str());
  if (settings.view == gl::DisplayView::Difference) {
    const std::string against = display.reference.empty() ? display.compareWith : display.reference;
    const DisplayDifference d =
        displayDifference(renderer.readLinear(), renderer.readComparison(), std::exp2(settings.exposure));
    std::printf(
        "difference %s - %s: %zu pixels, RMSE %.4g, max %.4g, mean %.4g 8-bit steps of displayed "
        "luminance; colour bar -%.4g (blue) .. +%.4g (red)\n",
        display.method.c_str(), against.c_str(), d.pixels, d.rmse * 255.0, d.maxAbs * 255.0, d.meanSigned * 255.0,
        display.differenceScale, display.differenceScale);
  }
  if (settings.view == gl::DisplayView::StandardError) {
    const StandardErrorSummary errors = summariseStandardErrors(viewed.mesh);
    std::printf(
        "standard errors of B (luminance, %zu nodes, mean B %.4g): median %.4g, 99th percentile %.4g, largest %.4g; "
        "colour bar 0 .. %.4g 8-bit steps of displayed luminance\n",
        errors.nodes, errors.meanB, errors.median, errors.p99, errors.largest, display.differenceScale);
  }
}

int runRender(const RenderOptions& options) {
  const std::optional<RayTracer> tracer = rayTracerFromName(options.display.method);
  const std::string& given = options.gather.givenWithGlMethod;
  const bool gatherOnly = given == "--gather-method" || given == "--gather-interpolant" || given == "--emitter-samples";
  if (!given.empty() && (gatherOnly ? tracer != RayTracer::FinalGather : !tracer)) {
    std::vector<std::string> takers;
    for (const RayTracerInfo& info : rayTracerRegistry())
      if (!gatherOnly || info.tracer == RayTracer::FinalGather) takers.push_back(info.name);
    throw Error(given + " needs --method " + joined(takers, " or "));
  }
  int width = 0, height = 0;
  parseSize(options.size, width, height);
  if (tracer) {
    checkRayTracedOptions(options.display, options.gather);  // before a scene's solve, not after
    checkImageMemory(options.size, width, height, kGatherBytesPerPixel, "the " + rayTracerInfo(*tracer).noun);
  } else if (options.display.view == "difference" || options.display.view == "standard-error" ||
             !options.linearOut.empty())
    checkImageMemory(options.size, width, height, kComparisonBytesPerPixel, "a render with its comparison");
  else
    checkImageMemory(options.size, width, height, kRenderBytesPerPixel, "the render");
  // The camera and the GL display options are refused before a scene's solve, not after it.
  auto checkOptions = [&](const LoadedFile& file) {
    const Bounds bounds = file.isSolution ? file.mesh.bounds() : file.scene.bounds();
    cameraFromSpec(options.display.camera, bounds, file.scene.cameras);
    if (!tracer) settingsFrom(options.display);
  };
  // A ray tracer that needs no solution (the path tracer) takes the surfaces alone: no solve.
  const bool solve = !tracer || rayTracerInfo(*tracer).needsSolution;
  const auto shared = std::make_shared<const ViewedFile>(
      openForViewing(options.file, options.display.elementSize, options.import, solve ? options.light : kDirectLight,
                     checkOptions, solveProgressOnTerminal(options.light)));
  const ViewedFile& viewed = *shared;
  for (const std::string& w : viewed.file.warnings) std::fprintf(stderr, "radview: warning: %s\n", w.c_str());
  if (tracer)
    renderRayTraced(viewed, options.display, options.gather, width, height, options.out, options.linearOut);
  else
    renderHeadless(shared, options.display, width, height, options.out, options.linearOut);
  if (!viewed.lighting.empty() && solve) std::printf("scene lighting: %s\n", viewed.lighting.c_str());
  return 0;
}

}  // namespace radview
