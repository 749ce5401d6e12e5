// Frame time of every interpolant and tessellation setting on the bundled Cornell box
// (direct light, default mesh), headless through EGL: render + glFinish, wall clock (on
// llvmpipe the GPU is the CPU, so this is the GPU time), median of the repetitions.
//   build/radview_frame_time_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only
#include "core/camera.h"
#include "gl/egl_context.h"
#include "gl/mesh_renderer.h"
#include "import/load_file.h"
#include "scene/camera_presets.h"
#include "solve/direct_light.h"

#include <benchmark/benchmark.h>

#include <memory>

namespace radview::gl {
namespace {

struct Fixture {
  EglContext context;
  MeshRenderer renderer;
  Camera camera;
  Fixture() {
    const LoadedFile file = loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/cornell_box.gltf");
    const RadiosityMesh mesh = meshAndLight(file.scene, defaultElementSize(file.scene));
    renderer.setMesh(mesh);
    camera = cameraFromSpec("file", mesh.bounds(), file.scene.cameras);
  }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

void frame(benchmark::State& state, Method method, int tessellation) {
  Fixture& f = fixture();
  RenderSettings settings;
  settings.method = method;
  settings.tessellation = tessellation;
  f.renderer.render(f.camera, settings, 1024, 1024);  // builds the pieces outside the timing
  glFinish();
  for (auto _ : state) {
    f.renderer.render(f.camera, settings, 1024, 1024);
    glFinish();
  }
  state.counters["patches"] = double(f.renderer.tessellationStatistics().patches);
  state.counters["level"] = f.renderer.tessellationStatistics().averageLevel;
}

void registerAll() {
  for (Method m : {Method::Flat, Method::Gouraud, Method::ScanlineGouraud, Method::Bilinear})
    benchmark::RegisterBenchmark(methodName(m).c_str(), frame, m, 0)->Unit(benchmark::kMillisecond);
  for (Method m : {Method::Quadratic, Method::C1Quadratic, Method::CloughTocher})
    for (int level : {0, 1, 4, 16, kAdaptiveTessellation}) {
      const std::string name = methodName(m) + "/" +
                               (level == 0  ? std::string("per-pixel")
                                : level < 0 ? std::string("adaptive")
                                            : "level-" + std::to_string(level));
      benchmark::RegisterBenchmark(name.c_str(), frame, m, level)->Unit(benchmark::kMillisecond)->MinTime(0.5);
    }
}

}  // namespace
}  // namespace radview::gl

int main(int argc, char** argv) {
  radview::gl::registerAll();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
