#pragma once
// The subcommands, each a plain options struct filled by CLI11 in main.cpp and a run
// function that returns the exit status. Errors are thrown as radview::Error.
#include "core/limits.h"
#include "gather/progressive_image.h"
#include "gl/mesh_renderer.h"
#include "app/scene_light.h"
#include "import/import_options.h"

#include <cstdint>
#include <memory>
#include <string>

namespace radview {

struct DisplayOptions {
  std::string method = "gouraud";
  bool screenSpace = false;  // Gouraud interpolated linearly in screen space
  double exposure = 0.0;     // stops
  std::string camera;        // preset or eye/target/up; empty: the file's camera, else front
  bool edges = false;
  std::string view = "normal";                // normal, value, gradient, isolines, difference
  std::string compareWith = "clough-tocher";  // difference view: the other method
  std::string reference;                      // difference view: an image to compare with instead
  double differenceScale = 4.0;               // difference view: 8-bit steps at the ends of the colour bar
  bool discontinuities = false;               // overlay discontinuity edges, coloured by order
  bool tVertices = false;                     // overlay T-vertex markers
  bool repairTVertices = false;               // triangulate elements through their T-vertices before drawing
  bool splitLines = false;                    // overlay the Bezier pieces' boundaries
  bool tessellationTriangles = false;         // overlay the generated triangles
  double surface = 0.0;                // radiosity surface (fig. 9.13): its height as a fraction of the scene; 0 off
  bool controlNet = false;             // with --surface: the Bezier control net
  std::string variant = "affine";      // clough-tocher: affine or book
  std::string smoothing = "auto";      // thin-plate: auto, by cross-validation, or lambda
  std::string tessellation = "per-pixel";  // quadratic and C1 methods: per-pixel, adaptive, or 1..64
  double tolerance = 0.5;              // adaptive tessellation: display error, in 8-bit steps
  double elementSize = 0.0;            // scenes only; 0 picks a default
};

// render --method final-gather (C&W §9.3.1) or path-trace: the passes, the seed, and what only the
// gather takes.
struct GatherOptions {
  int spp = 16;  // samples (passes) per pixel, 1 .. kMaxGatherSpp
  uint64_t seed = 1;
  std::string interpolant = "gouraud";  // B^ under the integral: a view-independent method
  int emitterSamples = 1;               // shadow rays per pixel per pass
  std::string givenWithGlMethod;        // a gather option given without final-gather, for the error
};

struct RenderOptions {
  std::string file;
  std::string out = "radview.png";
  std::string size = "1024x768";
  std::string linearOut;  // also write the linear radiosity (e.g. .exr), usable as a reference
  ImportOptions import;
  SceneLightOptions light;
  DisplayOptions display;
  GatherOptions gather;
};

struct InfoOptions {
  std::string file;
  double elementSize = 0.0;
  ImportOptions import;
};

// export: a solution (or a scene, solved or lit as the viewer shows it) to PLY or to a radview
// solution file, by the output's extension.
struct ExportOptions {
  std::string file;
  std::string out;
  double elementSize = 0.0;
  ImportOptions import;
  SceneLightOptions light;
};

struct SampleOptions {
  std::string file;
  std::string method = "clough-tocher";
  std::string points;                  // a file (.npy or text), '-' for standard input, or the points themselves
  std::string out;                     // a .npy file for the samples instead of text on standard output
  std::string diagonal = "02";         // gouraud: the quad diagonal, 02 or 13
  std::string camera;                  // scanline-gouraud: the view, as render --camera
  std::string size = "1024x768";       // scanline-gouraud: the view's image size
  std::string variant = "affine";      // clough-tocher: affine or book
  std::string smoothing = "auto";      // thin-plate: auto, by cross-validation, or lambda
  std::string tessellation = "per-pixel";  // quadratic and C1 methods: per-pixel, adaptive, or 1..64
  double tolerance = 0.5;              // adaptive tessellation: display error, in 8-bit steps
  bool estimateGradients = false;      // ignore gradients stored in the file
  bool standardError = false;          // also print the solver's standard error of B, interpolated linearly
  double maxDistance = -1.0;           // world points farther from every element are errors
  double elementSize = 0.0;
  ImportOptions import;
  SceneLightOptions light;
};

struct ViewerOptions {
  std::string file;  // empty: the bundled solved Cornell box (app/examples.h)
  int frames = 0;    // > 0: run that many frames, then exit
  std::string screenshot;
  std::string frameLog;  // a line per frame (app/frame_log.h)
  std::string size = "1280x800";
  ImportOptions import;
  SceneLightOptions light;  // a scene is solved in the background at once, unless directOnly
  DisplayOptions display;
  GatherOptions gather = viewerGather();  // the final gather in the window ('9', --method final-gather)
  bool framesWaitForSpp = false;          // --spp given: the last of --frames waits for the gather to reach it

  // As render's, but the gather converges until 1024 samples per pixel (the --spp a user can
  // wait for while looking; the panel changes it).
  static GatherOptions viewerGather() {
    GatherOptions gather;
    gather.spp = 1024;
    return gather;
  }
};

int runRender(const RenderOptions& options);
// The final gather's image as the GL renderer would display it, on its background colour
// (core/displayed_image.h).
Image displayedGather(const LinearImage& linear, double exposureScale);
int runInfo(const InfoOptions& options);
int runSample(const SampleOptions& options);
int runExport(const ExportOptions& options);
// Opens the window; where no display exists, renders headless to a PNG instead (unless a
// window was explicitly asked for with --frames/--screenshot) and prints its path.
int runViewer(const ViewerOptions& options);

struct ViewedFile;
// The renderer's settings the display options ask for. Throws Error for a bad one.
gl::RenderSettings settingsFrom(const DisplayOptions& display);
// --tessellation as gl::RenderSettings::tessellation. Throws Error.
int parseTessellation(const std::string& text);
// Renders through EGL to a PNG at `out` and prints its path.
// A difference view's statistics are printed after the path.
void renderHeadless(const std::shared_ptr<const ViewedFile>& viewed, const DisplayOptions& display, int width, int height,
                    const std::string& out, const std::string& linearOut = "");

// Draws the viewed file as `display` asks, through the GL renderer of the current context (an
// EglContext headless), at width x height; the renderer then holds the frame to read back.
// The renderer shares the viewed file's mesh, not a copy. Throws Error for a display option or a
// reference image that does not fit.
void drawHeadless(gl::MeshRenderer& renderer, const std::shared_ptr<const ViewedFile>& viewed,
                  const DisplayOptions& display, int width, int height);

// Throws Error for a gather option out of its range (--spp, --emitter-samples).
void checkGatherOptions(const GatherOptions& gather);
// Throws Error for a display option the GL renderer alone draws, or a gather option out of range.
void checkRayTracedOptions(const DisplayOptions& display, const GatherOptions& gather);
// The final gather's or the path tracer's estimate (display.method) of the viewed file's image from
// the display options' camera, before its first pass. Throws Error as checkRayTracedOptions, or
// where the file cannot be ray traced.
std::unique_ptr<ProgressiveImage> rayTracedEstimate(const ViewedFile& viewed, const DisplayOptions& display,
                                                    const GatherOptions& gather, int width, int height);
// The final gather's or the path tracer's image (display.method) of the viewed file to a PNG at
// `out` (and its linear radiosity at `linearOut`), with the display options' camera and
// exposure; prints the path and a summary. Throws Error for a GL-only display option or a bad
// gather option.
void renderRayTraced(const ViewedFile& viewed, const DisplayOptions& display, const GatherOptions& gather, int width,
                     int height, const std::string& out, const std::string& linearOut);

// "1024x768" -> width, height. Throws Error naming `option`.
void parseSize(const std::string& text, int& width, int& height, const std::string& option = "--size");
// Throws Error("--size TEXT: needs about ...") when `what`, at bytesPerPixel (core/memory_budget.h),
// would need more memory than is available.
void checkImageMemory(const std::string& sizeText, int width, int height, uint64_t bytesPerPixel,
                      const std::string& what);

}  // namespace radview
