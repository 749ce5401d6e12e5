#pragma once
// The C1 pieces of a whole mesh, built once from its triangulation and corner gradients:
// what the CPU interpolants evaluate and what the GPU uploads, so both show one surface.
// Across edges tagged C0 or C-1, creases and boundaries, each side is built from its own data
// alone (Salesin et al. 1992).
#include "interp/clough_tocher.h"
#include "interp/interpolant.h"
#include "interp/powell_sabin.h"
#include "interp/surface_triangulation.h"
#include "interp/vertex_gradients.h"

#include <vector>

namespace radview {

// Triangle t's Clough-Tocher element (C&W §9.2.2): what buildCloughTocherPatches holds for it,
// for callers that stream the elements rather than keep them all.
CloughTocherPatch cloughTocherPatch(const SurfaceTriangulation& surface, const CornerGradients& gradients,
                                    CloughTocherVariant variant, uint32_t t);
// One Clough-Tocher element per triangle of `surface`, built on every core.
std::vector<CloughTocherPatch> buildCloughTocherPatches(const SurfaceTriangulation& surface,
                                                        const CornerGradients& gradients, CloughTocherVariant variant);

// Triangle t's Powell-Sabin element (Reichert's C1 quadratic, C&W §9.2.2): split at its
// incenter, each edge cut where the segment joining the incenters on its two sides crosses it
// (its midpoint where the edge is not C1), which is what makes neighbours join C1. The
// incenters are computed where needed, a few operations each, rather than stored.
PowellSabinPatch powellSabinPatch(const SurfaceTriangulation& surface, const CornerGradients& gradients, uint32_t t);
// One Powell-Sabin element per triangle, built on every core.
std::vector<PowellSabinPatch> buildPowellSabinPatches(const SurfaceTriangulation& surface,
                                                      const CornerGradients& gradients);

}  // namespace radview
