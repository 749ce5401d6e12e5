#pragma once
// radview bench's reference image: the final gather (C&W eq. 9.9) or the path tracer at pixel
// centres, in independent runs whose spread is its noise (bench/error_estimate.h), sampled to
// --spp and then, with --precision, until every row's error interval is that narrow.
#include "app/bench_rows.h"
#include "app/command_bench.h"
#include "bench/bench_reference.h"
#include "gather/progressive_image.h"

#include <vector>

namespace radview {

// Adds passes to `estimate` as above, showing progress on standard error, and gives `reference`
// its runs; returns the samples per pixel reached and the seconds taken.
struct ReferenceRun {
  int spp = 0;
  double seconds = 0.0;
};
ReferenceRun convergeReference(ProgressiveImage& estimate, const BenchOptions& options,
                               const std::vector<MeasuredRow>& rows, BenchReference& reference);

}  // namespace radview
