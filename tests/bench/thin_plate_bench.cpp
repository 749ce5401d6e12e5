// The thin-plate smoothing spline's fit (interp/thin_plate.h), alone: smoothThinPlate with
// lambda chosen by cross-validation in every region, on the Cornell box meshed uniformly and
// lit directly (exact values, no standard errors), and on the same mesh with noise added to
// every node and its standard error stored (what a Monte Carlo solve hands over). Both cores.
//   ThinPlateFit/<element size in 1e-4>/<noisy>: 45 -> 1.4e5 elements (1.1e5 nodes),
//   16 -> 1.1e6 elements (8.9e5 nodes).
//   build/radview_thin_plate_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only
#include "core/display_transform.h"
#include "import/load_file.h"
#include "interp/thin_plate.h"
#include "solve/direct_light.h"

#include <benchmark/benchmark.h>

#include <map>
#include <random>

namespace radview {
namespace {

// Noise of 2 % of the mean luminance (a default solve's penumbrae are noisier, its lit areas
// cleaner), each node's standard error set to it.
RadiosityMesh withNoise(RadiosityMesh mesh) {
  double sum = 0.0;
  for (const Node& node : mesh.nodes) sum += luminance(node.B);
  const double sigma = 0.02 * sum / double(mesh.nodes.size());
  std::mt19937_64 random(1);
  std::normal_distribution<double> noise(0.0, sigma);
  for (Node& node : mesh.nodes) {
    const double e = noise(random);
    node.B += Rgb(e);
    node.standardError = Rgb(sigma);
  }
  mesh.hasStandardErrors = true;
  return mesh;
}

struct Meshes {
  RadiosityMesh exact, noisy;
  MeshTopology topology;
};

const Meshes& meshes(int elementSize) {
  static std::map<int, Meshes> byElementSize;
  auto it = byElementSize.find(elementSize);
  if (it == byElementSize.end()) {
    const Scene scene = loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/cornell_box.gltf").scene;
    RadiosityMesh exact = meshAndLight(scene, 1e-4 * elementSize);
    RadiosityMesh noisy = withNoise(exact);
    MeshTopology topology(exact);
    it = byElementSize.emplace(elementSize, Meshes{std::move(exact), std::move(noisy), std::move(topology)}).first;
  }
  return it->second;
}

void ThinPlateFit(benchmark::State& state) {
  const Meshes& m = meshes(int(state.range(0)));
  const RadiosityMesh& mesh = state.range(1) ? m.noisy : m.exact;
  ThinPlateReport report;
  for (auto _ : state) benchmark::DoNotOptimize(smoothThinPlate(mesh, m.topology, ThinPlateSettings{}, &report));
  size_t smoothed = 0;
  for (const ThinPlateRegion& region : report.regions) smoothed += region.smoothed;
  state.counters["elements"] = double(mesh.elements.size());
  state.counters["nodes"] = double(mesh.nodes.size());
  state.counters["regions smoothed"] = double(smoothed);
}
BENCHMARK(ThinPlateFit)->Args({45, 0})->Args({45, 1})->Args({16, 0})->Args({16, 1})->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
}  // namespace radview

BENCHMARK_MAIN();
