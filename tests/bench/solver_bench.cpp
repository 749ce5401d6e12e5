// The radiosity solver on the bundled Cornell box:
//  - SolverShot: rays per second of the first shot (from a light patch: form factors,
//    sampling, rays) to the 5,150 elements of the default uniform mesh (bounds diagonal / 40),
//    on both cores, against EmbreeOccluded1: Embree's rtcOccluded1 alone on the same rays (the
//    segments that shot casts, in the same frame), on both cores, and EmbreeOccluded1M: the same
//    rays as the solver casts them, each node's in one coherent stream;
//  - SolveTime/N: a whole solve with `radview solve`'s defaults (patches of diagonal / 12, to
//    1 % unshot; meshing included), subdivision up to N elements (tolerance 1 step, smallest
//    element the patch size / 64, so that the cap stops it).
//   build/radview_solver_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only
#include "core/parallel_for.h"
#include "geom/polygon.h"
#include "import/load_file.h"
#include "mesh/uniform_mesher.h"
#include "solve/element_to_node.h"
#include "solve/radiosity_solve.h"

#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <atomic>

namespace radview {
namespace {

struct Fixture {
  Scene scene;
  RadiosityMesh fine;
  Fixture() {
    scene = loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/cornell_box.gltf").scene;
    fine = meshUniformly(scene, scene.bounds().diagonal() / 40.0);
  }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

void SolverShot(benchmark::State& state) {
  Fixture& f = fixture();
  uint64_t rays = 0;
  for (auto _ : state) {
    state.PauseTiming();
    SolverSettings settings;
    settings.maxShots = 1;
    ProgressiveRefinement solver(f.scene, f.fine, settings);
    state.ResumeTiming();
    solver.step();  // the first shot: the light's patch of most power
    rays += solver.progress().rays;
  }
  state.counters["rays/s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
}

// The segments of the first shot: every node (as the solver places it) to every sample of the
// shooter in front of both, with the solver's sample streams.
// `groups`, when given, receives where each node's segments begin (and the end).
std::vector<Segment> firstShotSegments(const Fixture& f, std::vector<size_t>* groups = nullptr) {
  const RadiosityMesh& mesh = f.fine;
  uint32_t shooter = 0;
  double most = -1.0;
  for (uint32_t e = 0; e < mesh.elements.size(); ++e) {
    const Rgb E = mesh.materials[mesh.elements[e].material].E;
    const double power = (E.r + E.g + E.b) * area(mesh.cornerPositions(e));
    if (power > most) most = power, shooter = e;
  }
  const PatchSampler sampler(mesh.cornerPositions(shooter), SolverSettings{}.samples);
  const double diagonal = f.scene.bounds().diagonal();
  std::vector<Segment> segments;
  std::vector<char> done(mesh.nodes.size(), 0);
  std::vector<AreaSample> samples;
  for (uint32_t e = 0; e < mesh.elements.size(); ++e) {
    const Element& element = mesh.elements[e];
    if (element.surface == mesh.elements[shooter].surface) continue;
    const Vec3 n = unitNormal(f.scene.polygons[element.surface].vertices), inside = centroid(mesh.cornerPositions(e));
    for (uint32_t node : element.corners) {
      if (done[node]++) continue;
      const Vec3 toInside = inside - mesh.nodes[node].position;
      const Vec3 x = mesh.nodes[node].position +
                     std::min(0.01, 2.0 * RayCaster::kLift * diagonal / glm::length(toInside)) * toInside;
      if (groups) groups->push_back(segments.size());
      samples.clear();
      SampleStream stream = SampleStream::forKey(SolverSettings{}.seed, 0, node);
      sampler.draw(stream, samples);
      for (const AreaSample& s : samples) {
        const Vec3 d = s.position - x;
        if (glm::dot(n, d) > 0.0 && -glm::dot(sampler.normal(), d) > 0.0)
          segments.push_back({x, n, s.position, sampler.normal()});
      }
    }
  }
  if (groups) groups->push_back(segments.size());
  return segments;
}

void EmbreeOccluded1(benchmark::State& state) {
  Fixture& f = fixture();
  const RayCaster caster(f.scene);
  std::vector<RTCRay> rays;
  for (const Segment& segment : firstShotSegments(f)) {
    float origin[3], direction[3];
    RTCRay ray{};
    caster.embreeRay(segment, origin, direction, ray.tfar);
    ray.org_x = origin[0], ray.org_y = origin[1], ray.org_z = origin[2];
    ray.dir_x = direction[0], ray.dir_y = direction[1], ray.dir_z = direction[2];
    ray.mask = ~0u;
    rays.push_back(ray);
  }
  auto* scene = static_cast<RTCScene>(caster.embreeScene());
  std::atomic<uint64_t> occluded{0};
  for (auto _ : state) {
    parallelFor(
        rays.size(),
        [&](size_t i) {
          RTCRay ray = rays[i];
          RTCIntersectContext context;
          rtcInitIntersectContext(&context);
          rtcOccluded1(scene, &context, &ray);
          if (ray.tfar < 0.0f) ++occluded;
        },
        1024);
  }
  benchmark::DoNotOptimize(occluded.load());
  state.counters["rays/s"] = benchmark::Counter(double(rays.size()) * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["rays"] = double(rays.size());
}

// Embree alone on the same rays as the solver casts them: each node's rays in one coherent
// stream (rtcOccluded1M), on both cores.
void EmbreeOccluded1M(benchmark::State& state) {
  Fixture& f = fixture();
  const RayCaster caster(f.scene);
  std::vector<size_t> groups;
  std::vector<RTCRay> rays;
  for (const Segment& segment : firstShotSegments(f, &groups)) {
    float origin[3], direction[3];
    RTCRay ray{};
    caster.embreeRay(segment, origin, direction, ray.tfar);
    ray.org_x = origin[0], ray.org_y = origin[1], ray.org_z = origin[2];
    ray.dir_x = direction[0], ray.dir_y = direction[1], ray.dir_z = direction[2];
    ray.mask = ~0u;
    rays.push_back(ray);
  }
  auto* scene = static_cast<RTCScene>(caster.embreeScene());
  std::atomic<uint64_t> occluded{0};
  for (auto _ : state) {
    parallelFor(
        groups.size() - 1,
        [&](size_t g) {
          thread_local std::vector<RTCRay> batch;
          batch.assign(rays.begin() + long(groups[g]), rays.begin() + long(groups[g + 1]));
          RTCIntersectContext context;
          rtcInitIntersectContext(&context);
          context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
          rtcOccluded1M(scene, &context, batch.data(), unsigned(batch.size()), sizeof(RTCRay));
          for (const RTCRay& ray : batch)
            if (ray.tfar < 0.0f) ++occluded;
        },
        64);
  }
  benchmark::DoNotOptimize(occluded.load());
  state.counters["rays/s"] = benchmark::Counter(double(rays.size()) * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["rays"] = double(rays.size());
}

void SolveTime(benchmark::State& state) {
  Fixture& f = fixture();
  SolveSettings settings;
  settings.subdivision.maxElements = size_t(state.range(0));
  // Fine enough a tolerance and a smallest element that the cap is what stops subdivision.
  settings.subdivision.tolerance = 1.0;
  settings.subdivision.minElementSize = defaultPatchSize(f.scene) / 64.0;
  SolveSummary summary;
  for (auto _ : state) {
    const RadiosityMesh mesh = solveRadiosity(f.scene, settings, summary);
    benchmark::DoNotOptimize(mesh.nodes.data());
  }
  state.counters["elements"] = double(summary.progress.elements);
  state.counters["shots"] = double(summary.progress.shots);
  state.counters["rays/s"] = summary.progress.raysPerSecond();
}

BENCHMARK(SolverShot)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(EmbreeOccluded1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(EmbreeOccluded1M)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(SolveTime)
    ->Arg(1000)
    ->Arg(4000)
    ->Arg(16000)
    ->Arg(32000)
    ->Arg(64000)
    ->Arg(100000)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();

}  // namespace
}  // namespace radview

BENCHMARK_MAIN();
