#pragma once
// What `radview bench` measures: one row per method of the registry (interp/method_registry.h)
// and setting. Methods drawn as Bezier or Lagrange pieces are measured per pixel, at fixed
// tessellation levels and adaptively; the C1 ones also without relaxation along C0 edges,
// where the mesh has such edges (C&W §9.2.2: a C1 interpolant smooths a real kink away unless
// told where it is).
#include "interp/method_registry.h"

#include <string>
#include <vector>

namespace radview {

// A GL method at one setting: what a row renders.
struct BenchVariant {
  Method method = Method::Gouraud;
  int tessellation = 0;    // 0 per pixel, a level, or gl::kAdaptiveTessellation
  double tolerance = 0.5;  // adaptive: display error, 8-bit steps
  bool relaxed = true;     // C0 edges tagged (false: the mesh without its C0 tags)
  std::string setting;     // "per pixel", "level 4", "adaptive 0.5", with ", C0 not relaxed"
};

// In registry order; `adaptive` is the tessellation value that means adaptive.
std::vector<BenchVariant> benchVariants(const std::vector<int>& levels, const std::vector<double>& tolerances,
                                        bool meshHasC0Edges, int adaptive);

}  // namespace radview
