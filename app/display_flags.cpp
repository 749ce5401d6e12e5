#include "app/display_flags.h"

#include "app/method_choice.h"
#include "core/limits.h"
#include "core/strings.h"
#include "gl/mesh_renderer.h"
#include "interp/interpolant.h"
#include "scene/camera_presets.h"

#include <algorithm>
#include <cstdio>

namespace radview {

namespace {

// --view's help: every view's name and what it shows (gl/display_views.h).
std::string displayViewHelp() {
  std::vector<std::string> views;
  for (const gl::DisplayViewInfo& info : gl::displayViewRegistry())
    views.push_back(info.name + " (" + info.summary + ")");
  return "What the display shows: " + joined(views) + "; difference needs --compare-with or --reference";
}

}  // namespace

const char* const kFileHelp =
    "A glTF scene (.gltf/.glb), a radview solution file, or another tool's mesh with vertex colours "
    "(.ply, .obj, glTF with COLOR_0, ...)";
const char* const kSmoothingHelp =
    "thin-plate: lambda, the weight of bending against the misfit to the nodal values (0: the values "
    "themselves), or auto: chosen per region by generalised cross-validation";

// `methods`: the --method names the command accepts.
void addDisplayOptions(CLI::App& command, DisplayOptions& d, const std::vector<std::string>& methods) {
  std::string help = methodHelp();
  for (const RayTracerInfo& info : rayTracerRegistry())
    if (std::find(methods.begin(), methods.end(), info.name) != methods.end())
      help += "\n  " + info.name + ": " + info.summary + " (" + info.section + ")";
  command.add_option("--method", d.method, help)->check(methodChoice(methods))->capture_default_str();
  command.add_flag("--screen-space", d.screenSpace,
                   "Gouraud linear in screen space, as scanline hardware did, not perspective-correct");
  command.add_option("--exposure", d.exposure, "Exposure in stops: B is scaled by 2^X before display")
      ->check(CLI::Range(-40.0, 40.0))
      ->capture_default_str();
  command.add_option("--camera", d.camera,
                     "A preset (" + joined(cameraPresetNames()) +
                         ") or ex,ey,ez/tx,ty,tz[/ux,uy,uz]; "
                         "default: the file's camera, else front");
  command.add_flag("--edges", d.edges, "Overlay element edges");
  command.add_option("--view", d.view, displayViewHelp())
      ->check(CLI::IsMember(gl::displayViewNames()))
      ->capture_default_str();
  command
      .add_option("--compare-with", d.compareWith,
                  "--view difference: the method to subtract, evaluated exactly per pixel (a tessellated "
                  "method against itself shows its tessellation error)")
      ->check(methodChoice(methodNames()))
      ->capture_default_str();
  command.add_option("--reference", d.reference,
                     "--view difference: an image to subtract instead, the size of the render: a float file "
                     "(.exr, from render --linear-out) is linear radiosity, shown through the same exposure; "
                     "an 8-bit one (.png) is display colour");
  command
      .add_option("--difference-scale", d.differenceScale,
                  "--view difference: the difference, in 8-bit steps of displayed luminance, at the ends of "
                  "the colour bar; --view standard-error: the standard error at its top")
      ->capture_default_str();
  command.add_flag("--discontinuities", d.discontinuities,
                   "Overlay discontinuity edges: C-1 (value jumps) red, C0 (derivative jumps) yellow");
  command.add_flag("--t-vertices", d.tVertices, "Overlay T-vertices as magenta markers");
  command.add_flag("--split-lines", d.splitLines,
                   "c1-quadratic, clough-tocher: overlay the lines that cut elements into Bezier pieces");
  command.add_flag("--tessellation-triangles", d.tessellationTriangles,
                   "Tessellated methods: overlay the triangles the GPU generates");
  command.add_option("--surface", d.surface,
                     "quadratic, c1-quadratic, clough-tocher: draw the radiosity surface (fig. 9.13), B as a "
                     "height over each element, the tallest a fraction H of the scene's size (e.g. 0.15)");
  command.add_flag("--control-net", d.controlNet, "With --surface: draw the surface's Bezier control net (fig. 9.13)");
  command.add_flag("--repair-t-vertices", d.repairTVertices,
                   "Triangulate every element that has a T-vertex through it before drawing (Baum et al.)");
  command
      .add_option("--tessellation", d.tessellation,
                  "quadratic, c1-quadratic, clough-tocher: per-pixel (evaluated exactly at each pixel), adaptive (GPU-"
                  "tessellated until the display error is under --tolerance), or a fixed level 1..64")
      ->transform(CLI::Validator(
          [](std::string& value) {
            if (value == "exact") {  // kept for older scripts
              std::fprintf(stderr,
                           "radview: note: --tessellation exact is the older name of per-pixel, which "
                           "radview uses\n");
              value = "per-pixel";
            }
            return std::string();
          },
          ""))
      ->capture_default_str();
  command.add_option("--tolerance", d.tolerance, "Adaptive tessellation: largest display error, in 8-bit steps")
      ->check(CLI::Range(0.01, 100.0))
      ->capture_default_str();
  command
      .add_option("--variant", d.variant,
                  "clough-tocher: cross-boundary direction, affine (centroid to centroid) or book (edge normal)")
      ->check(CLI::IsMember({"affine", "book"}))
      ->capture_default_str();
  command.add_option("--smoothing", d.smoothing, kSmoothingHelp)->capture_default_str();
  command
      .add_option("--element-size", d.elementSize,
                  "Scenes: edge length of the uniform mesh's elements (default: bounds diagonal / 40)")
      ->check(CLI::Range(1e-12, 1e12));
}

// The final gather's options; `spp` says what --spp does for the command.
void addGatherOptions(CLI::App& command, GatherOptions& g, const std::string& spp) {
  command
      .add_option("--spp", g.spp, "final-gather, path-trace: " + spp + " (1.." + std::to_string(kMaxGatherSpp) + ")")
      ->capture_default_str();
  command.add_option("--seed", g.seed, "final-gather, path-trace: random seed (same seed, same image)")
      ->capture_default_str();
  addGatherMethodOption(command, g.interpolant,
                        "final-gather: the method that reconstructs B^ under the integral of eq. 9.9 (one that "
                        "needs no view)");
  command
      .add_option(
          "--emitter-samples", g.emitterSamples,
          "final-gather: shadow rays to the emitters per pixel per pass, 1.." + std::to_string(kMaxEmitterSamples))
      ->capture_default_str();
}

}  // namespace radview
