#include "app/command_bench.h"

#include "app/commands.h"
#include "app/import_flags.h"
#include "app/method_choice.h"
#include "app/viewed_file.h"
#include "bench/bench_variants.h"
#include "bench/image_error.h"
#include "bench/mach_bands.h"
#include "bench/tradeoff.h"
#include "core/atomic_file.h"
#include "core/camera.h"
#include "core/display_transform.h"
#include "core/error.h"
#include "core/image_difference.h"
#include "core/memory_budget.h"
#include "core/strings.h"
#include "gather/final_gather.h"
#include "gather/visible_elements.h"
#include "gl/egl_context.h"
#include "gl/mesh_renderer.h"
#include "interp/tessellation_level.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

namespace radview {

namespace {

std::vector<double> numberList(const std::string& text, const std::string& option) {
  std::vector<double> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const size_t first = item.find_first_not_of(' '), last = item.find_last_not_of(' ');
    const std::optional<double> v = first == std::string::npos
                                        ? std::nullopt
                                        : parseFiniteNumber(std::string_view(item).substr(first, last + 1 - first));
    if (!v) throw Error(option + " '" + text + "': expected numbers separated by commas");
    values.push_back(*v);
  }
  return values;
}

}  // namespace

CLI::App* addBenchCommand(CLI::App& app, BenchOptions& o) {
  CLI::App* command =
      app.add_subcommand("bench",
                         "Measure every method and setting on one view: GPU frame time, triangles, error against the "
                         "per-pixel final gather, Mach bands; writes a Markdown table, CSV and a plot");
  command->add_option("file", o.file, "A solution file, or a scene (meshed and lit directly)")->required();
  addImportOptions(*command, o.import);
  command->add_option("--camera", o.camera, "As render --camera");
  command->add_option("--size", o.size, "Image size WIDTHxHEIGHT")->capture_default_str();
  command->add_option("--exposure", o.exposure, "Exposure in stops")->capture_default_str();
  command->add_option("--spp", o.spp, "Samples per pixel of the final-gather reference")
      ->check(CLI::Range(1, kMaxGatherSpp))
      ->capture_default_str();
  command->add_option("--gather-interpolant", o.gatherInterpolant, "The reference's B^ under eq. 9.9's integral")
      ->check(methodChoice(methodNames(true)))
      ->capture_default_str();
  command->add_option("--frames", o.frames, "Timed frames per row (the median is reported)")
      ->check(CLI::Range(1, kMaxBenchFrames))
      ->capture_default_str();
  command
      ->add_option("--row-seconds", o.rowSeconds,
                   "Stop timing a row once its timed frames have taken this long and there are at least "
                   "3 of them (a row of 2-second frames needs no 9); 0 always times --frames")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  command->add_option("--levels", o.levels, "Tessellation levels, comma-separated, 1..64")->capture_default_str();
  command->add_option("--tolerances", o.tolerances, "Adaptive tessellation tolerances, 8-bit steps, comma-separated")
      ->capture_default_str();
  command
      ->add_option("--max-triangles-per-pixel", o.maxTrianglesPerPixel,
                   "Skip the fixed tessellation levels whose triangles would outnumber the pixels this many "
                   "times (the per-pixel row is as exact, and far cheaper); 0 measures every level")
      ->check(CLI::Range(0.0, 1e9))
      ->capture_default_str();
  command
      ->add_option("--out-dir", o.outDir,
                   "Where bench.md, bench.csv, bench.png, reference.exr/.png and each method's PNG go")
      ->capture_default_str();
  command->add_option("--element-size", o.elementSize, "Scenes: element size of the uniform mesh")
      ->check(CLI::Range(1e-12, 1e12));
  return command;
}

int runBench(const BenchOptions& options) {
  int width = 0, height = 0;
  parseSize(options.size, width, height);
  checkImageMemory(options.size, width, height, kBenchBytesPerPixel, "the bench's reference and renders");
  std::vector<int> levels;
  for (double level : numberList(options.levels, "--levels")) {
    if (level != std::floor(level) || level < 1 || level > kMaxTessellationLevel)
      throw Error("--levels: " + std::to_string(level) + " is not a level 1.." + std::to_string(kMaxTessellationLevel));
    levels.push_back(int(level));
  }
  const std::vector<double> tolerances = numberList(options.tolerances, "--tolerances");
  for (double t : tolerances)
    if (!(t >= 0.01 && t <= 100.0))
      throw Error("--tolerances: " + std::to_string(t) + " is not within 0.01..100 steps");
  std::error_code ec;
  std::filesystem::create_directories(options.outDir, ec);
  if (ec) throw Error(options.outDir, "cannot create the output folder: " + ec.message());

  const ViewedFile viewed = openForViewing(options.file, options.elementSize, options.import);
  checkFinalGatherRuns(viewed);  // the reference of every row
  const RadiosityMesh& mesh = viewed.mesh;
  const Camera camera = cameraFromSpec(options.camera, mesh.bounds(), viewed.file.scene.cameras);
  const double exposureScale = std::exp2(options.exposure);

  // The reference: the final gather at the same camera and size.
  GatherSettings gather;
  gather.interpolant = methodFromName(options.gatherInterpolant);
  gather.width = width;
  gather.height = height;
  gather.camera = camera;
  const auto start = std::chrono::steady_clock::now();
  FinalGather reference(mesh, gather);
  reference.addPasses(options.spp);
  const double gatherSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const ReferenceImage referenceImage{reference.image(), true, options.outDir + "/reference.exr"};
  writeLinearImage(referenceImage.pixels, referenceImage.path);
  writePng(displayedGather(referenceImage.pixels, exposureScale), options.outDir + "/reference.png");
  std::printf("reference: final gather, %d spp, B^ %s, %dx%d: %.1f s\n", options.spp, options.gatherInterpolant.c_str(),
              width, height, gatherSeconds);

  const std::vector<int32_t> elementAt = visibleElements(mesh, camera, width, height);
  const EdgeStencils stencils = edgeStencils(mesh, elementAt, width, height);
  // Errors are taken where a pixel and its four neighbours see one plane: along silhouettes
  // the reference antialiases (it averages the surfaces a pixel covers) and the GL renderer
  // does not, a difference of sampling, not of interpolation.
  const std::vector<char> interior = interiorPixels(mesh, elementAt, width, height);
  const double referenceMach = meanGradientJump(referenceImage.pixels, exposureScale, stencils.smooth);
  const double referenceKinks = meanGradientJump(referenceImage.pixels, exposureScale, stencils.c0);

  // Clough-Tocher without relaxation: the same mesh with its C0 tags dropped (C-1 edges keep
  // their separate nodes, so they stay C-1).
  RadiosityMesh unrelaxed = mesh;
  unrelaxed.discontinuities.erase(std::remove_if(unrelaxed.discontinuities.begin(), unrelaxed.discontinuities.end(),
                                                 [](const DiscontinuityEdge& d) { return d.order == Continuity::C0; }),
                                  unrelaxed.discontinuities.end());
  const bool hasC0 = unrelaxed.discontinuities.size() != mesh.discontinuities.size();

  const std::vector<BenchVariant> variants = benchVariants(levels, tolerances, hasC0, gl::kAdaptiveTessellation);

  gl::EglContext context;
  gl::MeshRenderer renderer;
  bool relaxedLoaded = true;
  renderer.setMesh(mesh);
  std::vector<TradeoffRow> rows;
  // Per method and mesh: the triangles of a frame at a fixed level L over L^2, measured at the
  // first level drawn. From it a finer level's count is known before it is drawn: at 10^5
  // elements and 1080p, level 32 makes 7e8 triangles and takes 44 s a frame on llvmpipe, for
  // an image the per-pixel row already shows exactly.
  std::map<std::pair<int, bool>, double> trianglesPerLevelSquared;
  std::vector<std::string> skipped;
  for (const BenchVariant& v : variants) {
    const bool fixedLevel = v.tessellation > 0 && v.tessellation != gl::kAdaptiveTessellation;
    const std::pair<int, bool> methodAndMesh{int(v.method), v.relaxed};
    const auto perLevelSquared = trianglesPerLevelSquared.find(methodAndMesh);
    if (fixedLevel && options.maxTrianglesPerPixel > 0.0 && perLevelSquared != trianglesPerLevelSquared.end() &&
        perLevelSquared->second * v.tessellation * v.tessellation >
            options.maxTrianglesPerPixel * double(width) * double(height)) {
      skipped.push_back(methodName(v.method) + " " + v.setting);
      continue;
    }
    if (v.relaxed != relaxedLoaded) {
      renderer.setMesh(v.relaxed ? mesh : unrelaxed);
      relaxedLoaded = v.relaxed;
    }
    gl::RenderSettings settings;
    settings.method = v.method;
    settings.tessellation = v.tessellation;
    settings.tessellationTolerance = v.tolerance / 255.0;
    settings.exposure = options.exposure;
    // Two frames first: the pieces are built, and the timer queries (read two frames late)
    // then time this setting only.
    for (int k = 0; k < 2; ++k) {
      renderer.render(camera, settings, width, height);
      glFinish();
    }
    std::vector<double> ms;
    const auto timingStart = std::chrono::steady_clock::now();
    for (int k = 0; k < options.frames; ++k) {
      renderer.render(camera, settings, width, height);
      glFinish();
      ms.push_back(renderer.gpuFrameMs());
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - timingStart).count();
      if (options.rowSeconds > 0.0 && ms.size() >= 3 && seconds >= options.rowSeconds) break;
    }
    TradeoffRow row;
    row.method = methodName(v.method);
    row.setting = v.setting;
    row.frameMs = median(ms);
    const auto& tess = renderer.tessellationStatistics();
    if (fixedLevel)
      trianglesPerLevelSquared[methodAndMesh] =
          double(tess.trianglesGenerated) / (double(v.tessellation) * v.tessellation);
    row.triangles = !methodInfo(v.method).bezierPieces() ? renderer.triangleCount()
                    : v.tessellation == 0                ? tess.patches
                                                         : tess.trianglesGenerated;
    if (v.tessellation == 0) {  // each method's picture, per pixel, beside the reference's
      std::string name = row.method + (v.relaxed ? "" : "-not-relaxed") + ".png";
      writePng(renderer.readDisplay(), options.outDir + "/" + name);
    }
    LinearImage image = renderer.readLinear();
    for (size_t p = 0; p < interior.size(); ++p)
      if (!interior[p]) image.rgba[4 * p + 3] = 0.0f;  // left out of every comparison below
    const LuminanceError error = luminanceError(image, referenceImage.pixels);
    row.rmse = error.rmse;
    row.maxError = error.max;
    const DisplayDifference shown = displayDifference(image, referenceImage, exposureScale);
    row.displayRmse = shown.rmse * 255.0;
    row.displayMax = shown.maxAbs * 255.0;
    row.machBands = meanGradientJump(image, exposureScale, stencils.smooth);
    row.c0Kinks = meanGradientJump(image, exposureScale, stencils.c0);
    std::fprintf(stderr, "%s %s: %.3g ms (median of %zu), display RMSE %.3g steps\n", row.method.c_str(),
                 row.setting.c_str(), row.frameMs, ms.size(), row.displayRmse);
    rows.push_back(row);
  }
  markParetoFront(rows);

  std::ostringstream header;
  header << "radview bench " << options.file << ": " << width << "x" << height << ", camera '"
         << (options.camera.empty() ? "default" : options.camera) << "', exposure " << options.exposure
         << "; reference " << options.spp << " spp final gather (B^ " << options.gatherInterpolant << ", "
         << gatherSeconds << " s); "
         << "its own Mach-band measure " << referenceMach << ", C0 kinks " << referenceKinks << " steps/px (noise "
         << "floor); " << stencils.smooth.size() << " stencils across untagged edges, " << stencils.c0.size()
         << " across C0 edges. Frame time: GPU timer queries, median of " << options.frames
         << " frames, or of at least 3 once they take " << options.rowSeconds << " s (--row-seconds).\n";
  if (!skipped.empty()) {
    header << "Not measured, their triangles more than " << options.maxTrianglesPerPixel
           << " times the pixels (--max-triangles-per-pixel):";
    for (size_t i = 0; i < skipped.size(); ++i) header << (i ? ", " : " ") << skipped[i];
    header << ".\n";
  }
  header << "\n";
  const std::string table = markdownTable(rows);
  writeFileAtomically(options.outDir + "/bench.md", header.str() + table);
  writeFileAtomically(options.outDir + "/bench.csv", csvTable(rows));
  const std::string title = std::filesystem::path(options.file).filename().string() + ", " + options.size;
  if (!writeTradeoffPlot(rows, title, options.outDir + "/bench.png"))
    std::fprintf(stderr, "radview: warning: no font (fonts-dejavu-core): the plot has no labels\n");
  std::printf("%s%s", header.str().c_str(), table.c_str());
  std::printf("wrote %s/bench.md, bench.csv, bench.png, reference.exr, reference.png and one PNG per method\n",
              options.outDir.c_str());
  return 0;
}

}  // namespace radview
