// radview: a viewer for radiosity solutions (Cohen & Wallace, Radiosity and Realistic Image
// Synthesis, §9.2-9.3). This file is the command line; each subcommand lives in its own file.
#include "app/command_bench.h"
#include "app/command_solve.h"
#include "app/commands.h"
#include "app/display_flags.h"
#include "app/examples.h"
#include "app/import_flags.h"
#include "app/method_choice.h"
#include "app/scene_light.h"
#include "app/viewer_keys.h"
#include "app/viewer_panel.h"
#include "core/camera.h"
#include "core/error.h"
#include "core/strings.h"
#include "gl/mesh_renderer.h"
#include "interp/interpolant.h"
#include "scene/camera_presets.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <exception>

using namespace radview;

int main(int argc, char** argv) {
  // Past a file size limit (ulimit -f) a write then fails with EFBIG, which radview reports with
  // the old file left intact (core/atomic_file.h), instead of SIGXFSZ killing it mid-write.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{
      "radview: a viewer for radiosity solutions (Cohen & Wallace §9.2-9.3).\n"
      "radview [FILE] opens the viewer (the bundled solved Cornell box without FILE); where no display\n"
      "exists it renders FILE headless to radview-<name>.png instead.",
      "radview"};
  app.footer(std::string("\n") + shortcutHelp());
  app.require_subcommand(0, 1);
  // One line, like every other radview error.
  app.failure_message(
      [](const CLI::App*, const CLI::Error& e) { return std::string("radview: ") + e.what() + " (see --help)\n"; });

  ViewerOptions viewer;
  app.add_option("file", viewer.file, kFileHelp);
  addImportOptions(app, viewer.import);
  addSceneLightOptions(app, viewer.light);
  app.add_option("--frames", viewer.frames, "Run the window for N frames, then exit")->check(CLI::Range(1, 1000000000));
  app.add_option("--screenshot", viewer.screenshot, "With --frames: write a PNG of the window (panel included)");
  app.add_option("--size", viewer.size, "Window size WIDTHxHEIGHT")->capture_default_str();
  app.add_option("--frame-log", viewer.frameLog,
                 "Write a line per frame to FILE: when it was shown (seconds since the epoch), its CPU time, the "
                 "method asked for and the one drawn, and the mesh's version (one more per edit or undo)");
  // Both the window and render draw with the interpolation methods and the ray tracers.
  const std::vector<std::string> methods = pictureMethodNames();
  addDisplayOptions(app, viewer.display, methods);
  addGatherOptions(app, viewer.gather,
                   "samples per pixel at which the window's gather stops (key 9 or --method final-gather); "
                   "given with --frames, the last frame waits for them");

  RenderOptions render;
  CLI::App* renderCommand = app.add_subcommand("render", "Render FILE headless (EGL) to a PNG");
  renderCommand->add_option("file", render.file, kFileHelp)->required();
  addImportOptions(*renderCommand, render.import);
  addSceneLightOptions(*renderCommand, render.light);
  renderCommand->add_option("--out,-o", render.out, "Output PNG")->capture_default_str();
  renderCommand->add_option("--size", render.size, "Image size WIDTHxHEIGHT")->capture_default_str();
  renderCommand->add_option("--linear-out", render.linearOut,
                            "Also write the linear radiosity as a float image (.exr): a reference for --reference");
  addDisplayOptions(*renderCommand, render.display, methods);
  addGatherOptions(*renderCommand, render.gather, "samples per pixel");

  InfoOptions info;
  CLI::App* infoCommand = app.add_subcommand("info",
                                             "Print what FILE holds: polygons, emitters, mesh, T-vertices, "
                                             "discontinuity edges, bounds");
  infoCommand->add_option("file", info.file, kFileHelp)->required();
  addImportOptions(*infoCommand, info.import);
  infoCommand
      ->add_option("--element-size", info.elementSize, "Scenes: element size of the uniform mesh that is reported")
      ->check(CLI::Range(1e-12, 1e12));

  SampleOptions sample;
  CLI::App* sampleCommand = app.add_subcommand(
      "sample", "Print the reconstructed radiosity B and its surface gradient at points (CPU reference)");
  sampleCommand->add_option("file", sample.file, kFileHelp)->required();
  addImportOptions(*sampleCommand, sample.import);
  addSceneLightOptions(*sampleCommand, sample.light);
  sampleCommand->add_option("--method", sample.method, methodHelp())
      ->check(methodChoice(methodNames()))
      ->capture_default_str();
  sampleCommand->add_option("--camera", sample.camera, "scanline-gouraud: the view it is seen in, as render --camera");
  sampleCommand->add_option("--size", sample.size, "scanline-gouraud: the image size of that view, WIDTHxHEIGHT")
      ->capture_default_str();
  sampleCommand
      ->add_option("--points", sample.points,
                   "Points: a file, '-' (standard input), or the text itself; one per line or ';'-separated, "
                   "each 'x y z' (world space, projected onto the nearest element) or 'element b0 b1 b2' "
                   "(barycentric in the element's first three corners); or a .npy array of such rows "
                   "(3 or 4 columns, float64 or float32)")
      ->required();
  sampleCommand->add_option("--out", sample.out,
                            "A .npy file for the samples (float64, one row per point, the text's columns) "
                            "instead of text on standard output");
  sampleCommand->add_option("--diagonal", sample.diagonal, "gouraud: cut quads along corners 02 or 13")
      ->check(CLI::IsMember({"02", "13"}))
      ->capture_default_str();
  sampleCommand
      ->add_option("--smoothing", sample.smoothing, kSmoothingHelp)
      ->capture_default_str();
  sampleCommand
      ->add_option("--variant", sample.variant,
                   "clough-tocher: cross-boundary direction, affine (centroid to centroid) or book "
                   "(edge normal)")
      ->check(CLI::IsMember({"affine", "book"}))
      ->capture_default_str();
  sampleCommand->add_flag("--estimate-gradients", sample.estimateGradients,
                          "Estimate vertex gradients even when the file stores them");
  sampleCommand->add_flag("--standard-error", sample.standardError,
                          "Also print the standard error of B the solver estimated (SE_r SE_g SE_b), "
                          "interpolated linearly between the nodes");
  sampleCommand
      ->add_option("--max-distance", sample.maxDistance,
                   "World points farther than this from every element are errors (default: 1e-3 of "
                   "the bounds diagonal)")
      ->check(CLI::NonNegativeNumber);
  sampleCommand->add_option("--element-size", sample.elementSize, "Scenes: element size of the uniform mesh")
      ->check(CLI::Range(1e-12, 1e12));

  ExportOptions exportOptions;
  CLI::App* exportCommand = app.add_subcommand(
      "export",
      "Write FILE's radiosity mesh as PLY (.ply: for MeshLab, CloudCompare, Blender) or as a radview "
      "solution file (.glb/.gltf), by OUT's extension");
  exportCommand->add_option("file", exportOptions.file, kFileHelp)->required();
  exportCommand->add_option("out", exportOptions.out, "The file to write: .ply, .glb or .gltf")->required();
  exportCommand
      ->add_option("--element-size", exportOptions.elementSize, "Scenes: element size of the uniform mesh written")
      ->check(CLI::Range(1e-12, 1e12));
  addImportOptions(*exportCommand, exportOptions.import);
  addSceneLightOptions(*exportCommand, exportOptions.light);

  SolveOptions solve;
  CLI::App* solveCommand = addSolveCommand(app, solve);
  BenchOptions bench;
  CLI::App* benchCommand = addBenchCommand(app, bench);

  CLI::App* keysCommand =
      app.add_subcommand("keys", "Print the viewer's keys and mouse as a Markdown table (README's list is this)");

  CLI11_PARSE(app, argc, argv);
  viewer.framesWaitForSpp = app.count("--spp") > 0;
  // The final gather's own options first, so that one of them is named where it is misplaced.
  for (const char* name : {"--gather-method", "--gather-interpolant", "--emitter-samples", "--spp", "--seed"})
    if (render.gather.givenWithGlMethod.empty() && renderCommand->count(name) > 0)
      render.gather.givenWithGlMethod = name;
  try {
    if (*renderCommand) return runRender(render);
    if (*infoCommand) return runInfo(info);
    if (*sampleCommand) return runSample(sample);
    if (*exportCommand) return runExport(exportOptions);
    if (*solveCommand) return runSolve(solve);
    if (*benchCommand) return runBench(bench);
    if (*keysCommand) {
      std::fputs(keysMarkdown().c_str(), stdout);
      return 0;
    }
    if (viewer.file.empty()) viewer.file = examplePath(bundledExamples().front());
    // A bundled example opens the way that shows what it demonstrates, unless told otherwise.
    if (const Example* example = exampleForFile(viewer.file); example && app.count("--method") == 0) {
      viewer.display.method = methodInfo(example->method).name;
      viewer.display.edges |= example->elementEdges;
      viewer.display.discontinuities |= example->discontinuityEdges;
      viewer.display.tVertices |= example->tVertices;
    }
    return runViewer(viewer);
  } catch (const Error& e) {
    std::fprintf(stderr, "radview: %s\n", e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "radview: unexpected failure: %s\n", e.what());
  }
  return 1;
}
