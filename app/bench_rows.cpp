#include "app/bench_rows.h"

#include "core/image.h"
#include "gl/bezier_pass.h"
#include "gl/frame_timing.h"
#include "interp/method_registry.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

namespace radview {

RenderedRows renderRows(gl::MeshRenderer& renderer, const RadiosityMesh& mesh, const RadiosityMesh& unrelaxed,
                        const std::vector<BenchVariant>& variants, const Camera& camera,
                        const BenchReference& reference, int width, int height, const BenchOptions& options) {
  RenderedRows result;
  bool relaxedLoaded = true;
  renderer.setMesh(mesh);
  // Per method and mesh: the triangles of a frame at a fixed level L over L^2, measured at the
  // first level drawn. From it a finer level's count is known before it is drawn: at 10^5
  // elements and 1080p, level 32 makes 7e8 triangles, for an image the per-pixel row already
  // shows exactly.
  std::map<std::pair<int, bool>, double> trianglesPerLevelSquared;
  for (const BenchVariant& v : variants) {
    const bool fixedLevel = v.tessellation > 0 && v.tessellation != gl::kAdaptiveTessellation;
    const std::pair<int, bool> methodAndMesh{int(v.method), v.relaxed};
    const auto perLevelSquared = trianglesPerLevelSquared.find(methodAndMesh);
    if (fixedLevel && options.maxTrianglesPerPixel > 0.0 && perLevelSquared != trianglesPerLevelSquared.end() &&
        perLevelSquared->second * v.tessellation * v.tessellation >
            options.maxTrianglesPerPixel * double(width) * double(height)) {
      result.skipped.push_back(methodName(v.method) + " " + v.setting);
      continue;
    }
    if (v.relaxed != relaxedLoaded) {
      renderer.setMesh(v.relaxed ? mesh : unrelaxed);
      relaxedLoaded = v.relaxed;
    }
    gl::RenderSettings settings;
    settings.method = v.method;
    settings.tessellation = v.tessellation;
    settings.tessellationTolerance = v.tolerance / 255.0;
    settings.exposure = options.exposure;
    const gl::FrameTimes times =
        gl::timeFrames(renderer, camera, settings, width, height, options.frames, options.rowSeconds);
    MeasuredRow measured;
    measured.variant = v;
    TradeoffRow& row = measured.row;
    row.method = methodName(v.method);
    row.setting = v.setting;
    row.frameMs = times.medianGpuMs();
    const auto& tess = renderer.tessellationStatistics();
    if (fixedLevel)
      trianglesPerLevelSquared[methodAndMesh] =
          double(tess.trianglesGenerated) / (double(v.tessellation) * v.tessellation);
    row.triangles = !methodInfo(v.method).bezierPieces() ? renderer.triangleCount()
                    : v.tessellation == 0                ? tess.patches
                                                         : tess.trianglesGenerated;
    if (v.tessellation == 0) {  // each method's picture, per pixel, beside the reference's
      std::string name = row.method + (v.relaxed ? "" : "-not-relaxed") + ".png";
      writePng(renderer.readDisplay(), options.outDir + "/" + name);
    }
    const LinearImage image = renderer.readLinear();
    row.image = rowFileStem(row) + ".exr";
    writeLinearImage(image, options.outDir + "/" + row.image);
    measured.values = reference.rowValues(image);
    auto meanAbs = [](const std::vector<float>& jumps) {
      double sum = 0.0;
      for (float j : jumps) sum += std::abs(j);
      return jumps.empty() ? 0.0 : sum / double(jumps.size());
    };
    row.machBands = meanAbs(measured.values.smoothJumps);
    row.c0Kinks = meanAbs(measured.values.c0Jumps);
    std::fprintf(stderr, "%s %s: %.3g ms (median of %zu)\n", row.method.c_str(), row.setting.c_str(), row.frameMs,
                 times.frames.size());
    result.rows.push_back(std::move(measured));
  }
  return result;
}

void splitErrors(gl::MeshRenderer& renderer, const Camera& camera, double exposureScale, int width, int height,
                 const RadiosityMesh& relaxed, const RadiosityMesh& unrelaxed, const NodalReference& nodal,
                 const BenchReference& reference, std::vector<MeasuredRow>& rows) {
  for (int k = 0; k < nodal.runs; ++k)
    for (bool isRelaxed : {true, false}) {
      bool loaded = false;
      for (MeasuredRow& m : rows) {
        if (m.rayTraced || m.variant.tessellation != 0 || m.variant.relaxed != isRelaxed) continue;
        if (!loaded) renderer.setMesh(nodal.withRun(isRelaxed ? relaxed : unrelaxed, k));
        loaded = true;
        gl::RenderSettings settings;
        settings.method = m.variant.method;
        settings.exposure = std::log2(exposureScale);
        renderer.render(camera, settings, width, height);
        m.fromNodes.push_back(reference.rowValues(renderer.readLinear()));
      }
    }
}

}  // namespace radview
