// radview: a viewer for radiosity solutions (Cohen & Wallace, Radiosity and Realistic Image
// Synthesis, §9.2-9.3). This file is the command line; each subcommand lives in its own file.
#include "app/asset_paths.h"
#include "app/commands.h"
#include "app/viewer_panel.h"
#include "core/camera.h"
#include "core/error.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

namespace {

using namespace radview;

std::string presetList() {
  std::string out;
  for (const std::string& name : cameraPresetNames()) out += (out.empty() ? "" : ", ") + name;
  return out;
}

void addDisplayOptions(CLI::App& command, DisplayOptions& d) {
  command.add_option("--method", d.method, "Interpolant: flat (one value per element) or gouraud (linear)")
      ->check(CLI::IsMember({"flat", "gouraud"}))
      ->capture_default_str();
  command.add_flag("--screen-space", d.screenSpace,
                   "Gouraud linear in screen space, as scanline hardware did, not perspective-correct");
  command.add_option("--exposure", d.exposure, "Exposure in stops: B is scaled by 2^X before display")
      ->check(CLI::Range(-40.0, 40.0))
      ->capture_default_str();
  command.add_option("--camera", d.camera,
                     "A preset (" + presetList() + ") or ex,ey,ez/tx,ty,tz[/ux,uy,uz]; "
                     "default: the file's camera, else front");
  command.add_flag("--edges", d.edges, "Overlay element edges");
  command.add_option("--element-size", d.elementSize,
                     "Scenes: edge length of the uniform mesh's elements (default: bounds diagonal / 40)")
      ->check(CLI::PositiveNumber);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"radview: a viewer for radiosity solutions (Cohen & Wallace §9.2-9.3).\n"
               "radview [FILE] opens the viewer (the bundled Cornell box without FILE); where no display\n"
               "exists it renders FILE headless to radview-<name>.png instead.",
               "radview"};
  app.footer(std::string("\n") + shortcutHelp());
  app.require_subcommand(0, 1);

  ViewerOptions viewer;
  app.add_option("file", viewer.file, "A glTF scene (.gltf/.glb) or a radview solution file");
  app.add_option("--frames", viewer.frames, "Run the window for N frames, then exit")->check(CLI::PositiveNumber);
  app.add_option("--screenshot", viewer.screenshot, "With --frames: write a PNG of the window (panel included)");
  app.add_option("--size", viewer.size, "Window size WIDTHxHEIGHT")->capture_default_str();
  addDisplayOptions(app, viewer.display);

  RenderOptions render;
  CLI::App* renderCommand = app.add_subcommand("render", "Render FILE headless (EGL) to a PNG");
  renderCommand->add_option("file", render.file, "A glTF scene or radview solution file")
      ->required();
  renderCommand->add_option("--out,-o", render.out, "Output PNG")->capture_default_str();
  renderCommand->add_option("--size", render.size, "Image size WIDTHxHEIGHT")->capture_default_str();
  addDisplayOptions(*renderCommand, render.display);

  InfoOptions info;
  CLI::App* infoCommand = app.add_subcommand("info", "Print what FILE holds: polygons, emitters, mesh, T-vertices, "
                                                     "discontinuity edges, bounds");
  infoCommand->add_option("file", info.file, "A glTF scene or radview solution file")
      ->required();
  infoCommand->add_option("--element-size", info.elementSize,
                          "Scenes: element size of the uniform mesh that is reported")
      ->check(CLI::PositiveNumber);

  CLI11_PARSE(app, argc, argv);
  try {
    if (*renderCommand) return runRender(render);
    if (*infoCommand) return runInfo(info);
    if (viewer.file.empty()) viewer.file = bundledScenePath();
    return runViewer(viewer);
  } catch (const Error& e) {
    std::fprintf(stderr, "radview: %s\n", e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "radview: unexpected failure: %s\n", e.what());
  }
  return 1;
}
