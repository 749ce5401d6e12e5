#pragma once
// radview bench's rows drawn by the GL renderer: each method and setting timed on the view and
// its linear image kept, with the values the error estimates take from it; and the per-pixel
// rows drawn again from the nodal reference's runs, for the error split.
#include "app/command_bench.h"
#include "bench/bench_reference.h"
#include "bench/bench_variants.h"
#include "bench/nodal_reference.h"
#include "bench/tradeoff.h"
#include "core/camera.h"
#include "gl/mesh_renderer.h"
#include "mesh/radiosity_mesh.h"

#include <string>
#include <vector>

namespace radview {

// A row measured: what the table reports of it, and its values for the error estimates.
struct MeasuredRow {
  BenchVariant variant;
  TradeoffRow row;
  RowValues values;
  std::vector<RowValues> fromNodes;  // per pixel: its method drawing each run of the nodal reference
  bool rayTraced = false;            // the final gather's row (--reference path-trace), not a GL method
};

struct RenderedRows {
  std::vector<MeasuredRow> rows;
  std::vector<std::string> skipped;  // "method setting" of the levels --max-triangles-per-pixel left out
};

// Every variant drawn on `renderer` (relaxed: `mesh`; not: `unrelaxed`), its frame time the
// median GPU time (gl/frame_timing.h); each per-pixel picture written as METHOD.png and every
// row's linear image as its .exr under options.outDir.
RenderedRows renderRows(gl::MeshRenderer& renderer, const RadiosityMesh& mesh, const RadiosityMesh& unrelaxed,
                        const std::vector<BenchVariant>& variants, const Camera& camera,
                        const BenchReference& reference, int width, int height, const BenchOptions& options);

// The per-pixel rows drawn again from each run of the nodal reference (bench/nodal_reference.h):
// the values their error splits on, into each row's fromNodes.
void splitErrors(gl::MeshRenderer& renderer, const Camera& camera, double exposureScale, int width, int height,
                 const RadiosityMesh& relaxed, const RadiosityMesh& unrelaxed, const NodalReference& nodal,
                 const BenchReference& reference, std::vector<MeasuredRow>& rows);

}  // namespace radview
