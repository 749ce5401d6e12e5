#pragma once
// What a solution's standard errors (Node::standardError, the solver's estimate of each nodal
// B's noise) say in a few numbers, in luminance (C&W §9.2's last paragraph: nodal values as
// noisy samples). Visibility noise is the same in R, G and B (the channels share their rays),
// so the luminance of a node's standard errors is the standard error of its luminance.
#include "mesh/radiosity_mesh.h"

#include <cstddef>

namespace radview {

struct StandardErrorSummary {
  size_t nodes = 0;      // of non-emitting elements (all nodes when every element emits)
  size_t uncertain = 0;  // of those, with a standard error above 0
  double median = 0.0, p99 = 0.0, largest = 0.0;  // over `nodes`
  double meanB = 0.0;                             // their mean luminance, the scale to read them at
};

// Throws Error when the mesh has no standard errors (RadiosityMesh::hasStandardErrors).
StandardErrorSummary summariseStandardErrors(const RadiosityMesh& mesh);

}  // namespace radview
