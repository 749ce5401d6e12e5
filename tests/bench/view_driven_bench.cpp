// Meshing for the view against meshing for every view (C&W §9.3), at equal element budgets.
// The Cornell box is solved view-independently at a sweep of budgets, and for each view at the
// budgets asked; every solution is rendered from the view (Gouraud and Clough-Tocher, through
// EGL) and compared with one reference per view, the per-pixel final gather (eq. 9.9) over the
// finest view-independent solution, as `radview bench` compares: display RMSE in 8-bit steps
// over the pixels whose neighbours see the same plane, against what the gather converges to
// (its four runs' noise taken out, bench/bench_reference.h), +- the 95 % interval's half-width.
// The table gives, for each view-driven
// solve, the elements with which the view-independent solve first has the same error or less
// (elementsForError).
//   build/radview_view_bench [--size WxH] [--spp N] [--budgets 600,1000,2000] [--sweep 600,...,32000]
//                            [--tolerance STEPS] [--view NAME=CAMERA]...
#include "bench/bench_reference.h"
#include "bench/image_error.h"
#include "core/camera.h"
#include "gather/final_gather.h"
#include "gl/egl_context.h"
#include "gl/mesh_renderer.h"
#include "import/load_file.h"
#include "mesh/uniform_mesher.h"
#include "scene/camera_presets.h"
#include "solve/radiosity_solve.h"
#include "trace/visible_elements.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace radview {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::vector<size_t> countList(const char* text) {
  std::vector<size_t> counts;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) counts.push_back(std::strtoull(item.c_str(), nullptr, 10));
  return counts;
}

struct Solved {
  RadiosityMesh mesh;
  double seconds = 0.0;
};

Solved solve(const Scene& scene, size_t budget, double tolerance, const std::vector<SolveView>& views) {
  SolveSettings settings;
  settings.subdivision.maxElements = budget;
  settings.subdivision.tolerance = tolerance;
  settings.subdivision.views = views;
  // Finer than radview solve's default (the patch size / 16), so that a close view's budget is
  // not cut short by the smallest element first.
  settings.subdivision.minElementSize = defaultPatchSize(scene) / 64.0;
  SolveSummary summary;
  const auto start = Clock::now();
  Solved solved{solveRadiosity(scene, settings, summary), 0.0};
  solved.seconds = secondsSince(start);
  return solved;
}

// The display error in 8-bit steps of a method's render of `mesh` against the reference.
ErrorEstimate displayError(gl::MeshRenderer& renderer, const RadiosityMesh& mesh, Method method, const SolveView& view,
                           const BenchReference& reference) {
  renderer.setMesh(mesh);
  gl::RenderSettings settings;
  settings.method = method;
  renderer.render(view.camera, settings, view.width, view.height);
  return reference.error(reference.rowValues(renderer.readLinear())).display;
}

// "4.54±0.05": an estimate and its 95 % interval's larger half.
std::string steps(const ErrorEstimate& e) {
  char text[48];
  std::snprintf(text, sizeof text, "%.2f±%.2f", e.rms(), std::max(e.rms() - e.rmsLow(), e.rmsHigh() - e.rms()));
  return text;
}

struct Errors {
  size_t elements = 0;
  double gouraud = 0.0, cloughTocher = 0.0;   // the estimates, display steps
  std::string gouraudText, cloughTocherText;  // with their intervals
};

// The elements with which the view-independent sweep first reaches `target`, interpolated in
// log(elements), log(error) between its first solve that does and the one before; the first
// solve's count if that one does, 0 if none does. The first, not the last crossing: the error
// is not monotone in the element count (at small budgets a round of splits can add more
// overshoot than it removes), and the first crossing never favours the view-driven solve.
double elementsForError(const std::vector<Errors>& sweep, double Errors::*error, double target) {
  for (size_t i = 0; i < sweep.size(); ++i) {
    if (sweep[i].*error > target) continue;
    if (i == 0) return double(sweep[0].elements);
    const double x0 = std::log(double(sweep[i - 1].elements)), x1 = std::log(double(sweep[i].elements));
    const double y0 = std::log(sweep[i - 1].*error), y1 = std::log(sweep[i].*error);
    return std::exp(x0 + (std::log(target) - y0) / (y1 - y0) * (x1 - x0));
  }
  return 0.0;
}

std::string needed(double elements, const std::vector<Errors>& sweep) {
  char text[64];
  if (elements > 0.0)
    std::snprintf(text, sizeof text, "%.0f", elements);
  else
    std::snprintf(text, sizeof text, "> %zu", sweep.back().elements);
  return text;
}

std::string ratio(double elements, size_t viewDriven) {
  char text[64];
  if (elements > 0.0)
    std::snprintf(text, sizeof text, "%.2f", double(viewDriven) / elements);
  else
    std::snprintf(text, sizeof text, "-");
  return text;
}

}  // namespace
}  // namespace radview

int main(int argc, char** argv) {
  using namespace radview;
  int width = 384, height = 288, spp = 512;
  double tolerance = 1.0;
  std::vector<size_t> budgets = {600, 1000, 2000},
                      sweep = {600, 1000, 1500, 2000, 3000, 4000, 6000, 8000, 16000, 32000};
  std::vector<std::pair<std::string, std::string>> viewSpecs;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--size"))
      std::sscanf(argv[i + 1], "%dx%d", &width, &height);
    else if (!std::strcmp(argv[i], "--spp"))
      spp = std::max(1, std::atoi(argv[i + 1]));
    else if (!std::strcmp(argv[i], "--budgets"))
      budgets = countList(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--sweep"))
      sweep = countList(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--tolerance"))
      tolerance = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--view") && std::strchr(argv[i + 1], '='))
      viewSpecs.push_back({std::string(argv[i + 1], std::strchr(argv[i + 1], '=')), std::strchr(argv[i + 1], '=') + 1});
    else {
      std::fprintf(stderr, "radview_view_bench: unknown option %s\n", argv[i]);
      return 2;
    }
  }
  if (viewSpecs.empty())
    viewSpecs = {{"published", "file"},
                 // Close up into the back right corner, over the short block: a fifth of the
                 // box's surfaces in view.
                 {"corner", "0.2,0.3,0.25/0.0,0.05,0.559"}};
  try {
    gl::EglContext context;
    const LoadedFile file = loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/cornell_box.gltf");
    const Scene& scene = file.scene;
    std::vector<SolveView> views;
    for (const auto& [name, spec] : viewSpecs)
      views.push_back({cameraFromSpec(spec, scene.bounds(), scene.cameras), width, height, name});

    std::printf("%s\nCornell box, %dx%d, tolerance %g steps, smallest element the patch size / 64\n",
                context.description().c_str(), width, height, tolerance);
    // How much of the scene each view sees: the patches (the initial mesh) with a pixel.
    const RadiosityMesh patches = meshUniformly(scene, defaultPatchSize(scene));
    for (const SolveView& view : views) {
      size_t seen = 0;
      for (uint32_t p : viewedPixels(patches, {view})) seen += p > 0;
      std::printf("view '%s': %zu of the %zu patches in view\n", view.name.c_str(), seen, patches.elements.size());
    }
    std::vector<Solved> independent;
    for (size_t budget : sweep) {
      independent.push_back(solve(scene, budget, tolerance, {}));
      std::fprintf(stderr, "view-independent, budget %zu: %zu elements, %.1f s\n", budget,
                   independent.back().mesh.elements.size(), independent.back().seconds);
    }
    gl::MeshRenderer renderer;
    std::vector<std::vector<Errors>> sweepOf;  // per view
    std::printf(
        "\n| view | budget | view-independent: elements, Gouraud / CT RMSE | view-driven: elements, Gouraud / CT "
        "RMSE | view-independent elements for the same error, Gouraud / CT | view-driven / those |\n"
        "|---|---|---|---|---|---|\n");
    for (const SolveView& view : views) {
      const RadiosityMesh& finest = independent.back().mesh;
      GatherSettings gather;
      gather.interpolant = Method::CloughTocher;
      gather.width = width;
      gather.height = height;
      gather.camera = view.camera;
      gather.runs = 4;
      gather.pixelCentres = true;
      FinalGather reference(finest, gather);
      reference.addPasses((spp + gather.runs - 1) / gather.runs * gather.runs);
      const std::vector<char> interior =
          interiorPixels(finest, visibleElements(finest, view.camera, width, height), width, height);
      std::vector<uint32_t> pixels;
      for (size_t p = 0; p < interior.size(); ++p)
        if (interior[p]) pixels.push_back(uint32_t(p));
      BenchReference yardstick(width, height, pixels, {}, {}, 1.0);
      std::vector<LinearImage> runs;
      for (int r = 0; r < gather.runs; ++r) runs.push_back(reference.runImage(r));
      yardstick.setRuns(runs);
      auto errorsOf = [&](const RadiosityMesh& mesh) {
        const ErrorEstimate g = displayError(renderer, mesh, Method::Gouraud, view, yardstick);
        const ErrorEstimate c = displayError(renderer, mesh, Method::CloughTocher, view, yardstick);
        return Errors{mesh.elements.size(), g.rms(), c.rms(), steps(g), steps(c)};
      };
      std::vector<Errors> sweepErrors;
      for (const Solved& s : independent) sweepErrors.push_back(errorsOf(s.mesh));
      for (size_t budget : budgets) {
        const Solved driven = solve(scene, budget, tolerance, {view});
        const Errors d = errorsOf(driven.mesh);
        size_t at = 0;
        while (at < sweep.size() && sweep[at] != budget) ++at;
        const Errors p = at < sweep.size() ? sweepErrors[at] : errorsOf(solve(scene, budget, tolerance, {}).mesh);
        const double gouraudNeeds = elementsForError(sweepErrors, &Errors::gouraud, d.gouraud);
        const double ctNeeds = elementsForError(sweepErrors, &Errors::cloughTocher, d.cloughTocher);
        std::printf("| %s | %zu | %zu, %s / %s | %zu, %s / %s | %s / %s | %s / %s |\n", view.name.c_str(), budget,
                    p.elements, p.gouraudText.c_str(), p.cloughTocherText.c_str(), d.elements, d.gouraudText.c_str(),
                    d.cloughTocherText.c_str(), needed(gouraudNeeds, sweepErrors).c_str(),
                    needed(ctNeeds, sweepErrors).c_str(), ratio(gouraudNeeds, d.elements).c_str(),
                    ratio(ctNeeds, d.elements).c_str());
        std::fflush(stdout);
        std::fprintf(stderr, "%s, budget %zu: view-driven solve %.1f s\n", view.name.c_str(), budget, driven.seconds);
      }
      sweepOf.push_back(sweepErrors);
    }
    std::printf("\nThe view-independent sweep, display RMSE in steps, Gouraud / CT:\n\n| elements |");
    for (const SolveView& view : views) std::printf(" %s |", view.name.c_str());
    std::printf("\n|---|");
    for (size_t i = 0; i < views.size(); ++i) std::printf("---|");
    std::printf("\n");
    for (size_t i = 0; i < independent.size(); ++i) {
      std::printf("| %zu |", independent[i].mesh.elements.size());
      for (const std::vector<Errors>& errors : sweepOf)
        std::printf(" %s / %s |", errors[i].gouraudText.c_str(), errors[i].cloughTocherText.c_str());
      std::printf("\n");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "radview_view_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
