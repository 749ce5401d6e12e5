// The interpolants at scale: the Cornell box meshed finer and finer (10^4 to 10^6 elements),
// rendered headless through EGL at 1920x1080 from the scene's camera.
// Frame time (gl/frame_timing.h, the wall time to each frame's end): methods are interleaved frame by frame with
// Gouraud between each two, round after round (G m1 G m2 ... G, each round starting one method later), so that a shared
// machine's slow spells fall on every method and on the Gouraud frames beside it alike; each
// method's median is reported with its interquartile range, and its ratio to Gouraud as the
// median over rounds of its time over the mean of the two Gouraud frames beside it. Seconds to
// the first frame (pieces built, uploaded, drawn, finished) are measured once per method.
// Memory and wall time: `radview render` of the same mesh, as a user runs it (meshing, direct
// light, set-up, one frame, PNG), once per method per round, interleaved the same way: its
// peak resident memory (as /usr/bin/time -f %M reports it; on llvmpipe the GPU's buffers are
// part of it) and its wall time, each with its median ratio to the Gouraud runs beside it.
// Every ratio comes with its range over the rounds, how far one round can be trusted.
//   build/radview_scale_bench [--element-size S]... [--rounds N] [--render-rounds N] [--size WxH]
//                             [--methods gouraud,clough-tocher]
#include "core/camera.h"
#include "gl/egl_context.h"
#include "gl/frame_timing.h"
#include "gl/mesh_renderer.h"
#include "import/load_file.h"
#include "interp/method_registry.h"
#include "scene/camera_presets.h"
#include "solve/direct_light.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace radview::gl {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double at = q * double(v.size() - 1);
  const size_t i = size_t(at);
  return i + 1 < v.size() ? v[i] + (at - double(i)) * (v[i + 1] - v[i]) : v.back();
}

// What one method measured, sample by sample, and each sample over the mean of the Gouraud
// samples taken just before and just after it.
struct Series {
  std::vector<double> samples, ratios;
};

// Runs measure(i) -> std::array<double, N> (N quantities of method i, Gouraud being 0) in
// rounds of G m G m ... G, each round starting one method later so that no method always
// follows the same one (the first draw after another renderer's pays for its caches going
// cold). A slow spell longer than two samples slows both sides of a ratio alike; the methods'
// own order in a round is no longer part of it. Returns per method its N series.
template <size_t N, class Measure>
std::vector<std::array<Series, N>> interleaveWithGouraud(size_t methods, int rounds, Measure measure) {
  std::vector<std::array<Series, N>> series(methods);
  auto keep = [&](size_t method, const std::array<double, N>& values) {
    for (size_t q = 0; q < N; ++q) series[method][q].samples.push_back(values[q]);
  };
  for (int round = 0; round < rounds; ++round) {
    std::array<double, N> before = measure(0);
    keep(0, before);
    for (size_t step = 0; step + 1 < methods; ++step) {
      const size_t i = 1 + (step + size_t(round)) % (methods - 1);
      const std::array<double, N> value = measure(i);
      const std::array<double, N> after = measure(0);
      keep(i, value);
      keep(0, after);
      for (size_t q = 0; q < N; ++q) series[i][q].ratios.push_back(2.0 * value[q] / (before[q] + after[q]));
      before = after;
    }
  }
  for (size_t q = 0; q < N; ++q) series[0][q].ratios.assign(size_t(rounds), 1.0);
  return series;
}

// A method's ratios to the Gouraud samples beside it, over rounds: "median (lowest-highest)".
std::string ratioOverRounds(const Series& series) {
  const std::vector<double>& ratios = series.ratios;
  char text[64];
  std::snprintf(text, sizeof text, "%.2f (%.2f-%.2f)", quantile(ratios, 0.5), quantile(ratios, 0.0),
                quantile(ratios, 1.0));
  return text;
}

struct RenderRun {
  double peakMb = 0.0, seconds = 0.0;
};

// One `radview render` of the Cornell box meshed at `elementSize` with `method`, its output
// discarded: its peak resident memory and the wall time. Throws if it fails. GNU time starts
// it and reads its peak: a process started from this one directly would count this one's
// memory too (Linux keeps the larger peak of the memory image a process replaces on exec).
RenderRun renderRun(double elementSize, const char* method, int width, int height) {
  const std::string stem = "/tmp/radview_scale_bench_" + std::to_string(getpid());
  const std::string out = stem + ".png", peakFile = stem + ".peak";
  char elementSizeText[32];
  std::snprintf(elementSizeText, sizeof elementSizeText, "%g", elementSize);
  std::vector<std::string> args = {"/usr/bin/time",
                                   "-f",
                                   "%M",
                                   "-o",
                                   peakFile,
                                   RADVIEW_BINARY,
                                   "render",
                                   std::string(RADVIEW_SOURCE_DIR) + "/assets/cornell_box.gltf",
                                   "--direct-only",  // the mesh lit as measureFrames' is, not solved
                                   "--element-size",
                                   elementSizeText,
                                   "--size",
                                   std::to_string(width) + "x" + std::to_string(height),
                                   "--method",
                                   method,
                                   "-o",
                                   out};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  const auto start = Clock::now();
  pid_t child = 0;
  const int spawned = posix_spawn(&child, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error("cannot run /usr/bin/time (Debian's package time)");
  int status = 0;
  waitpid(child, &status, 0);
  const double seconds = secondsSince(start);
  double peakKb = 0.0;
  std::ifstream(peakFile) >> peakKb;
  std::remove(out.c_str());
  std::remove(peakFile.c_str());
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !(peakKb > 0.0))
    throw std::runtime_error(std::string("radview render --method ") + method + " failed");
  return {peakKb / 1024.0, seconds};
}

void measure(const LoadedFile& file, double elementSize, int rounds, int renderRounds, int width, int height,
             const std::string& only) {
  const auto meshStart = Clock::now();
  const RadiosityMesh mesh = meshAndLight(file.scene, elementSize);
  const double meshSeconds = secondsSince(meshStart);
  const Camera camera = cameraFromSpec("file", mesh.bounds(), file.scene.cameras);
  // The registry's methods, each per pixel, Gouraud first, always: the others are measured
  // against it.
  std::vector<Method> variants = {Method::Gouraud};
  for (const MethodInfo& info : methodRegistry())
    if (info.method != Method::Gouraud &&
        (only.empty() || ("," + only + ",").find("," + info.name + ",") != std::string::npos))
      variants.push_back(info.method);
  // One renderer per method, so that each keeps its pieces between rounds, as a viewer would.
  std::vector<std::unique_ptr<MeshRenderer>> renderers;
  std::vector<double> firstFrame;
  auto perPixel = [](Method method) {
    RenderSettings settings;
    settings.method = method;
    return settings;
  };
  for (Method method : variants) {
    const auto start = Clock::now();
    renderers.push_back(std::make_unique<MeshRenderer>());
    renderers.back()->setMesh(mesh);
    timeFrame(*renderers.back(), camera, perPixel(method), width, height);
    firstFrame.push_back(secondsSince(start));
  }
  const auto frames = interleaveWithGouraud<1>(variants.size(), rounds, [&](size_t i) {
    return std::array<double, 1>{timeFrame(*renderers[i], camera, perPixel(variants[i]), width, height).wallMs};
  });
  std::printf("\n%zu elements (--element-size %g), meshed and lit in %.2f s; %dx%d, %d rounds\n", mesh.elements.size(),
              elementSize, meshSeconds, width, height, rounds);
  std::printf(
      "| method | median ms | IQR ms | / Gouraud (range over rounds) | first frame s |\n"
      "|---|---|---|---|---|\n");
  for (size_t i = 0; i < variants.size(); ++i) {
    const Series& ms = frames[i][0];
    std::printf("| %s | %.1f | %.1f-%.1f | %s | %.2f |\n", methodName(variants[i]).c_str(), quantile(ms.samples, 0.5),
                quantile(ms.samples, 0.25), quantile(ms.samples, 0.75), ratioOverRounds(ms).c_str(), firstFrame[i]);
  }
  std::fflush(stdout);
  if (renderRounds == 0) return;
  renderers.clear();
  const auto runs = interleaveWithGouraud<2>(variants.size(), renderRounds, [&](size_t i) {
    const RenderRun run = renderRun(elementSize, methodName(variants[i]).c_str(), width, height);
    return std::array<double, 2>{run.peakMb, run.seconds};
  });
  std::printf(
      "\n`radview render`, %d rounds\n| method | peak MB | / Gouraud (range) | wall s | / Gouraud (range) "
      "|\n|---|---|---|---|---|\n",
      renderRounds);
  for (size_t i = 0; i < variants.size(); ++i) {
    const Series &peakMb = runs[i][0], &seconds = runs[i][1];
    std::printf("| %s | %.0f | %s | %.2f | %s |\n", methodName(variants[i]).c_str(), quantile(peakMb.samples, 0.5),
                ratioOverRounds(peakMb).c_str(), quantile(seconds.samples, 0.5), ratioOverRounds(seconds).c_str());
  }
  std::fflush(stdout);
}

}  // namespace
}  // namespace radview::gl

int main(int argc, char** argv) {
  using namespace radview;
  std::vector<double> sizes;
  int rounds = 40, renderRounds = 7, width = 1920, height = 1080;
  std::string methods;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--element-size"))
      sizes.push_back(std::atof(argv[i + 1]));
    else if (!std::strcmp(argv[i], "--rounds"))
      rounds = std::max(1, std::atoi(argv[i + 1]));
    else if (!std::strcmp(argv[i], "--render-rounds"))
      renderRounds = std::max(0, std::atoi(argv[i + 1]));
    else if (!std::strcmp(argv[i], "--size"))
      std::sscanf(argv[i + 1], "%dx%d", &width, &height);
    else if (!std::strcmp(argv[i], "--methods"))
      methods = argv[i + 1];
    else {
      std::fprintf(stderr, "radview_scale_bench: unknown option %s\n", argv[i]);
      return 2;
    }
  }
  if (sizes.empty()) sizes = {0.01, 0.005};
  try {
    gl::EglContext context;
    std::printf("%s\n", context.description().c_str());
    const LoadedFile file = loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/cornell_box.gltf");
    for (double s : sizes) gl::measure(file, s, rounds, renderRounds, width, height, methods);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "radview_scale_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
