#include "bench/bench_variants.h"

#include <cstdio>

namespace radview {

std::vector<BenchVariant> benchVariants(const std::vector<int>& levels, const std::vector<double>& tolerances,
                                        bool meshHasC0Edges, int adaptive) {
  std::vector<BenchVariant> variants;
  for (const MethodInfo& info : methodRegistry()) {
    const Method m = info.method;
    // Thin-plate's pieces are Clough-Tocher's, tessellated alike: what it changes is the values,
    // which its per-pixel row measures.
    if (!info.bezierPieces() || m == Method::ThinPlate) {
      variants.push_back({m, 0, 0.5, true, "per pixel"});
      continue;
    }
    for (bool relaxed : {true, false}) {
      if (!relaxed && !(info.c1 && meshHasC0Edges)) continue;
      const std::string suffix = relaxed ? "" : ", C0 not relaxed";
      variants.push_back({m, 0, 0.5, relaxed, "per pixel" + suffix});
      for (int level : levels) variants.push_back({m, level, 0.5, relaxed, "level " + std::to_string(level) + suffix});
      for (double t : tolerances) {
        char name[48];
        std::snprintf(name, sizeof name, "adaptive %g", t);
        variants.push_back({m, adaptive, t, relaxed, name + suffix});
      }
    }
  }
  return variants;
}

}  // namespace radview
