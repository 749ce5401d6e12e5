// radview render --method final-gather: C&W §9.3.1's per-pixel evaluation of eq. 9.9, radview's
// accuracy reference, written as the GL renders are (same camera, exposure and tone map), so
// that its --linear-out is a --reference for --view difference of any GL method.
#include "app/commands.h"
#include "app/viewed_file.h"
#include "core/camera.h"
#include "core/displayed_image.h"
#include "core/error.h"
#include "gather/final_gather.h"

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

void renderFinalGather(const ViewedFile& viewed, const DisplayOptions& display, const GatherOptions& options, int width,
                       int height, const std::string& out, const std::string& linearOut) {
  const std::string glOnly = glOnlyOptionGiven(display);
  if (!glOnly.empty()) throw Error(glOnly + ": a GL display option, not available with --method final-gather");
  checkGatherOptions(options);
  checkFinalGatherRuns(viewed);

  GatherSettings settings;
  settings.interpolant = methodFromName(options.interpolant);
  settings.interpolantOptions.cloughTocher = cloughTocherVariantFromName(display.variant);
  settings.seed = options.seed;
  settings.width = width;
  settings.height = height;
  settings.camera = cameraFromSpec(display.camera, viewed.mesh.bounds(), viewed.file.scene.cameras);
  settings.emitterSamples = options.emitterSamples;
  const auto start = std::chrono::steady_clock::now();
  FinalGather gather(viewed.mesh, settings);
  const bool progress = isatty(fileno(stderr));
  auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  while (gather.samplesPerPixel() < options.spp) {
    gather.addPasses(1);
    if (progress)
      std::fprintf(stderr, "\rfinal gather: %d/%d spp, %.1f s", gather.samplesPerPixel(), options.spp, seconds());
  }
  if (progress) std::fprintf(stderr, "\n");
  const double elapsed = seconds();

  const LinearImage image = gather.image();
  writePng(displayedGather(image, std::exp2(display.exposure)), out);
  if (!linearOut.empty()) writeLinearImage(image, linearOut);
  std::printf("%s\n", out.c_str());
  std::printf("final gather: %d spp, %dx%d, B^ %s, seed %llu: %.2f s (setup included), %.3g M rays, %.3g M rays/s\n",
              gather.samplesPerPixel(), width, height, options.interpolant.c_str(),
              static_cast<unsigned long long>(options.seed), elapsed, double(gather.raysCast()) * 1e-6,
              double(gather.raysCast()) * 1e-6 / elapsed);
}

}  // namespace radview
