#include "app/command_bench.h"

#include "app/bench_reference_run.h"
#include "app/bench_rows.h"
#include "app/commands.h"
#include "app/import_flags.h"
#include "app/method_choice.h"
#include "app/solve_progress_bar.h"
#include "bench/bench_reference.h"
#include "bench/bench_variants.h"
#include "bench/error_map.h"
#include "bench/image_error.h"
#include "bench/mach_bands.h"
#include "bench/nodal_reference.h"
#include "bench/tradeoff.h"
#include "core/atomic_file.h"
#include "core/camera.h"
#include "core/error.h"
#include "core/limits.h"
#include "core/memory_budget.h"
#include "core/strings.h"
#include "gather/final_gather.h"
#include "gather/path_tracer.h"
#include "gather/traced_surfaces.h"
#include "gl/egl_context.h"
#include "gl/frame_timing.h"
#include "gl/mesh_renderer.h"
#include "interp/method_registry.h"
#include "interp/tessellation_level.h"
#include "scene/camera_presets.h"
#include "trace/visible_elements.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
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

// --truth: a linear image of the bench's size, every pixel finite and non-negative.
LinearImage readTruth(const std::string& path, int width, int height) {
  if (!std::filesystem::exists(path)) throw Error(path, "--truth: no such file");
  const ReferenceImage image = readReferenceImage(path);
  if (!image.linear)
    throw Error(path,
                "--truth: holds display colour (8 or 16-bit integers); it must be linear radiosity in a float "
                "format such as OpenEXR");
  if (image.pixels.width != width || image.pixels.height != height)
    throw Error(path, "--truth: is " + std::to_string(image.pixels.width) + "x" + std::to_string(image.pixels.height) +
                          ", the bench renders " + std::to_string(width) + "x" + std::to_string(height) + " (--size)");
  for (size_t i = 0; i < image.pixels.rgba.size(); ++i) {
    const float v = image.pixels.rgba[i];
    if (i % 4 == 3) continue;
    const std::string where = "pixel " + std::to_string(i / 4 % size_t(width)) + ", " +
                              std::to_string(i / 4 / size_t(width)) + " (from the top left)";
    if (!std::isfinite(v)) throw Error(path, "--truth: " + where + " is not a finite number");
    if (v < 0.0f) throw Error(path, "--truth: " + where + " is negative (" + std::to_string(v) + ")");
  }
  return image.pixels;
}

// The ray tracer that makes the reference image: --reference gather or path-trace.
RayTracer referenceTracer(const BenchOptions& options) {
  return options.reference == rayTracerInfo(RayTracer::PathTrace).name ? RayTracer::PathTrace : RayTracer::FinalGather;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The ends of the error maps' diverging scale, and the red end of the reference's noise map,
// display steps.
constexpr double kErrorMapSteps = 10.0, kNoiseMapSteps = 1.0;

}  // namespace

CLI::App* addBenchCommand(CLI::App& app, BenchOptions& o) {
  CLI::App* command =
      app.add_subcommand("bench",
                         "Measure every method and setting on one view: GPU frame time, triangles, error against the "
                         "per-pixel final gather (its noise taken out, with 95 % intervals), Mach bands; writes a "
                         "Markdown table, CSV, a plot and every row's linear image");
  command->add_option("file", o.file, "A solution file, or a scene (meshed and lit directly)")->required();
  addImportOptions(*command, o.import);
  command->add_option("--camera", o.camera, "As render --camera");
  command->add_option("--size", o.size, "Image size WIDTHxHEIGHT")->capture_default_str();
  command->add_option("--exposure", o.exposure, "Exposure in stops")->capture_default_str();
  command
      ->add_option("--reference", o.reference,
                   "The reference image: gather (eq. 9.9 per pixel over the solution: the interpolants' trade, the "
                   "solution taken as right) or path-trace (the true image: the solution's error counted too, and "
                   "the final gather a row like the others)")
      ->check(CLI::IsMember(std::vector<std::string>{"gather", rayTracerInfo(RayTracer::PathTrace).name}))
      ->capture_default_str();
  command
      ->add_option("--gather-spp", o.gatherRowSpp,
                   "--reference path-trace: samples per pixel of the final gather's row (its time and error)")
      ->check(CLI::Range(1, kMaxGatherSpp))
      ->capture_default_str();
  command->add_option("--spp", o.spp, "Samples per pixel of the reference, all runs together")
      ->check(CLI::Range(1, kMaxGatherSpp))
      ->capture_default_str();
  command
      ->add_option("--runs", o.runs,
                   "Independent runs of the reference, each its own sample sequences: their spread is its noise, "
                   "which the error estimates take out")
      ->check(CLI::Range(4, kMaxGatherRuns))
      ->capture_default_str();
  command
      ->add_option("--precision", o.precision,
                   "Add reference passes until every row's 95 % interval is narrower than twice this (display "
                   "steps), or --max-seconds; 0: --spp only")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  command
      ->add_option("--node-spp", o.nodeSpp,
                   "Samples per node of the reference at the mesh's nodes, which splits each per-pixel row's error "
                   "into the solution's part and the reconstruction's; 0: no split")
      ->check(CLI::Range(0, kMaxGatherSpp))
      ->capture_default_str();
  command
      ->add_option("--max-seconds", o.maxSeconds, "With --precision: stop adding passes after this long; 0: no limit")
      ->check(CLI::Range(0.0, 1e9))
      ->capture_default_str();
  command->add_option(
      "--truth", o.truth,
      "Measure against this linear image (OpenEXR or another float format, the bench's size) instead "
      "of the gather: an analytic answer, a path tracer's render of the view; exact errors, no interval");
  addGatherMethodOption(*command, o.gatherMethod, "The method of the reference's B^ under eq. 9.9's integral");
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
                   "Where bench.md, bench.csv, bench.png, reference.exr/.png, each method's PNG and each row's "
                   "linear EXR go")
      ->capture_default_str();
  command->add_option("--element-size", o.elementSize, "Scenes: element size of the mesh (the solve's patches)")
      ->check(CLI::Range(1e-12, 1e12));
  addSceneLightOptions(*command, o.light);
  return command;
}

std::vector<TradeoffRow> measureTrade(const BenchOptions& options) {
  const auto benchStart = std::chrono::steady_clock::now();
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
  // A bad --truth is refused before minutes of work.
  const std::optional<LinearImage> truth =
      options.truth.empty() ? std::nullopt : std::optional<LinearImage>(readTruth(options.truth, width, height));
  std::error_code ec;
  std::filesystem::create_directories(options.outDir, ec);
  if (ec) throw Error(options.outDir, "cannot create the output folder: " + ec.message());

  const ViewedFile viewed = openForViewing(options.file, options.elementSize, options.import, options.light, nullptr,
                                           solveProgressOnTerminal(options.light));
  if (!truth)  // the reference of every row
    checkRayTracingRuns(viewed, "the " + rayTracerInfo(referenceTracer(options)).noun);
  const RadiosityMesh& mesh = viewed.mesh;
  const Camera camera = cameraFromSpec(options.camera, mesh.bounds(), viewed.file.scene.cameras);
  const double exposureScale = std::exp2(options.exposure);

  const std::vector<int32_t> elementAt = visibleElements(mesh, camera, width, height);
  EdgeStencils stencils = edgeStencils(mesh, elementAt, width, height);
  // Errors are taken where a pixel and its four neighbours see one plane: along silhouettes
  // a path tracer's reference antialiases (it averages the surfaces a pixel covers) and the GL
  // renderer does not, a difference of sampling, not of interpolation.
  const std::vector<char> interior = interiorPixels(mesh, elementAt, width, height);
  std::vector<uint32_t> compared;
  for (size_t p = 0; p < interior.size(); ++p)
    if (interior[p]) compared.push_back(uint32_t(p));
  BenchReference reference(width, height, std::move(compared), std::move(stencils.smooth), std::move(stencils.c0),
                           exposureScale);

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
  const RenderedRows rendered =
      renderRows(renderer, mesh, unrelaxed, variants, camera, reference, width, height, options);
  std::vector<MeasuredRow> rows = rendered.rows;
  const std::vector<std::string>& skipped = rendered.skipped;

  std::ostringstream header;
  header << "radview bench " << options.file << ": " << width << "x" << height << ", camera '"
         << (options.camera.empty() ? "default" : options.camera) << "', exposure " << options.exposure << ".\n";
  if (!viewed.lighting.empty()) header << "Scene lighting: " << viewed.lighting << ".\n";
  if (truth) {
    reference.setExact(*truth);
    writePng(displayedGather(reference.mean(), exposureScale), options.outDir + "/reference.png");
    header << "Reference: " << options.truth << ", exact: every error below is exact, with no interval.\n";
  } else {
    const bool pathTrace = referenceTracer(options) == RayTracer::PathTrace;
    GatherSettings gather;
    gather.interpolant = methodFromName(options.gatherMethod);
    gather.width = width;
    gather.height = height;
    gather.camera = camera;
    gather.runs = options.runs;
    gather.pixelCentres = true;
    PathTraceSettings traced;
    traced.width = width;
    traced.height = height;
    traced.camera = camera;
    traced.runs = options.runs;
    traced.pixelCentres = true;
    std::unique_ptr<FinalGather> finalGather;
    std::unique_ptr<PathTracer> tracer;
    if (pathTrace)
      tracer = std::make_unique<PathTracer>(tracedSurfaces(viewed), traced);
    else
      finalGather = std::make_unique<FinalGather>(mesh, gather);
    ProgressiveImage& estimate = pathTrace ? static_cast<ProgressiveImage&>(*tracer) : *finalGather;
    const ReferenceRun run = convergeReference(estimate, options, rows, reference);
    const int spp = run.spp;
    const double seconds = run.seconds;
    writeLinearImage(reference.mean(), options.outDir + "/reference.exr");
    writePng(displayedGather(reference.mean(), exposureScale), options.outDir + "/reference.png");
    writePng(magnitudeMap(width, height, reference.pixels(), reference.pixelNoiseSteps(), kNoiseMapSteps),
             options.outDir + "/reference-noise.png");
    header << (pathTrace ? std::string("Reference: the path tracer's true image (no solution used)")
                         : "Reference: final gather (C&W eq. 9.9, B^ " + options.gatherMethod + ")")
           << " at each pixel's centre, " << spp << " spp in " << options.runs << " independent runs, "
           << number(seconds) << " s; its noise (RMS, over the compared pixels) " << number(reference.noiseLinear())
           << " linear, " << number(reference.noiseSteps()) << " display steps (reference-noise.png: white 0, red "
           << kNoiseMapSteps << " step or more).\n";
    if (pathTrace) {
      // The final gather as one more way to show the solution: its cost and its error against
      // the truth, which holds the solution's error and the gather's own noise.
      GatherSettings rowGather = gather;
      rowGather.runs = 1;
      const auto start = std::chrono::steady_clock::now();
      FinalGather rowEstimate(mesh, rowGather);
      rowEstimate.addPasses(options.gatherRowSpp);
      MeasuredRow measured;
      measured.rayTraced = true;
      measured.row.method = rayTracerInfo(RayTracer::FinalGather).name;
      measured.row.setting = "per pixel, " + std::to_string(options.gatherRowSpp) + " spp";
      measured.row.frameMs = 1e3 * secondsSince(start);
      const LinearImage image = rowEstimate.image();
      writePng(displayedGather(image, exposureScale), options.outDir + "/" + measured.row.method + ".png");
      measured.row.image = rowFileStem(measured.row) + ".exr";
      writeLinearImage(image, options.outDir + "/" + measured.row.image);
      measured.values = reference.rowValues(image);
      rows.push_back(std::move(measured));
      header << "The final-gather row: eq. 9.9 over the solution (B^ " << options.gatherMethod << ") at "
             << options.gatherRowSpp << " spp (--gather-spp); its time is the CPU's to those samples on all cores, "
             << "not a GPU frame, and its error includes its own noise.\n";
    }
    if (options.nodeSpp > 0) {
      const auto start = std::chrono::steady_clock::now();
      // Only the nodes the picture depends on, and no more samples at them than the image had:
      // at 10^6 elements most nodes are out of view, and the rest outnumber nothing but pixels.
      const std::vector<char> wanted = nodesOfTheView(mesh, elementAt);
      const size_t nodes = size_t(std::count(wanted.begin(), wanted.end(), char(1)));
      const double imageSamples = double(width) * double(height) * double(spp);
      const int perRun = std::max(
          1, int(std::min(double(options.nodeSpp), imageSamples / double(std::max<size_t>(nodes, 1))) / options.runs));
      std::fprintf(stderr, "the reference at %zu nodes, %d spp\n", nodes, perRun * options.runs);
      const NodalReference nodal = pathTrace ? pathTraceAtNodes(mesh, *tracer, perRun, wanted)
                                             : gatherAtNodes(mesh, *finalGather, perRun, wanted);
      splitErrors(renderer, camera, exposureScale, width, height, mesh, unrelaxed, nodal, reference, rows);
      header << "Where the error lives: " << (pathTrace ? "the true B" : "eq. 9.9") << " at the " << nodes
             << " nodes the view depends on, " << perRun * options.runs << " spp each (--node-spp " << options.nodeSpp
             << ", at most the image's samples in all) in the same runs, " << number(secondsSince(start))
             << " s with the per-pixel rows drawn from those values; the solution's part is the row against its "
                "method drawing them, the reconstruction's part that drawing against the reference image.\n";
    }
  }
  for (MeasuredRow& m : rows) {
    const RowError e = reference.error(m.values);
    TradeoffRow& row = m.row;
    row.rmse = e.rmse;
    row.maxError = e.maxError;
    row.displayRmse = e.displayRmse;
    row.displayMax = e.displayMax;
    row.linearError = e.linear;
    row.displayError = e.display;
    row.machError = e.smoothJumps;
    row.c0KinkError = e.c0Jumps;
    row.referenceNoiseRmse = reference.noiseLinear();
    row.referenceNoiseSteps = reference.noiseSteps();
    if (!m.fromNodes.empty()) {
      const ErrorSplit split = reference.split(m.values, m.fromNodes);
      row.solutionPart = split.solution;
      row.reconstructionPart = split.reconstruction;
      row.nodeNoiseSteps = split.nodeNoiseSteps;
      row.split = true;
    }
  }
  // Where each row loses: its difference from the reference, read back from its own file.
  for (const MeasuredRow& m : rows) {
    const LinearImage image = readReferenceImage(options.outDir + "/" + m.row.image).pixels;
    const std::string stem = options.outDir + "/" + rowFileStem(m.row) + "-error";
    writeLinearImage(signedDifference(image, reference.mean(), reference.pixels()), stem + ".exr");
    writePng(differenceMap(image, reference.mean(), reference.pixels(), exposureScale, kErrorMapSteps), stem + ".png");
  }
  std::vector<TradeoffRow> table;
  for (const MeasuredRow& m : rows) table.push_back(m.row);
  markParetoFront(table);

  const ErrorEstimate ownMach = reference.ownJumps(false), ownKinks = reference.ownJumps(true);
  header << "Errors are the root mean square over " << reference.pixelCount()
         << " pixels whose four neighbours see the same plane, against what the reference converges to: its noise "
            "is taken out (renderer/bench/error_estimate.h). [95 %] intervals are over the reference's sampling; "
            "rows whose intervals overlap are ties. Mach and C0 kink errors: the RMS difference of each row's "
            "gradient jumps from the reference's, over "
         << reference.stencilCount(false) << " stencils across untagged edges and " << reference.stencilCount(true)
         << " across C0 edges; the reference's own RMS jumps (noise taken out) are " << withInterval(ownMach) << " and "
         << withInterval(ownKinks) << " steps/px. Frame time: GPU timer queries, median of " << options.frames
         << " frames, or of at least 3 once they take " << options.rowSeconds
         << " s (--row-seconds). Error maps (*-error.png): row minus reference in displayed luminance, blue -"
         << kErrorMapSteps << " to red +" << kErrorMapSteps
         << " steps; *-error.exr the same in linear RGB. Whole bench: " << number(secondsSince(benchStart)) << " s.\n";
  if (!skipped.empty()) {
    header << "Not measured, their triangles more than " << options.maxTrianglesPerPixel
           << " times the pixels (--max-triangles-per-pixel):";
    for (size_t i = 0; i < skipped.size(); ++i) header << (i ? ", " : " ") << skipped[i];
    header << ".\n";
  }
  header << "\n";
  std::string text =
      header.str() + markdownTable(table) + "\nPer pixel, by error (display steps), with ties:\n\n" + tieReport(table);
  const std::string where = splitReport(table);
  if (!where.empty()) text += "\nWhere the error lives (display steps; intervals over the runs):\n\n" + where;
  writeFileAtomically(options.outDir + "/bench.md", text);
  writeFileAtomically(options.outDir + "/bench.csv", csvTable(table));
  const std::string title = std::filesystem::path(options.file).filename().string() + ", " + options.size;
  if (!writeTradeoffPlot(table, title, options.outDir + "/bench.png"))
    std::fprintf(stderr, "radview: warning: no font (fonts-dejavu-core): the plot has no labels\n");
  std::printf("%s", text.c_str());
  std::printf(
      "wrote %s/bench.md, bench.csv, bench.png, reference.png%s, one PNG per method, one EXR per row and its error "
      "map\n",
      options.outDir.c_str(), truth ? "" : ", reference.exr, reference-noise.png");
  return table;
}

int runBench(const BenchOptions& options) {
  measureTrade(options);
  return 0;
}

}  // namespace radview
