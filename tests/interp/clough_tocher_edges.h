#pragma once
// The Clough-Tocher element's cross-boundary directions as the tests set them (C&W §9.2 step 2):
// the book's edge normal, or the affine-invariant direction (scipy's) without a neighbour.
#include "interp/clough_tocher.h"

#include <array>
#include <optional>

namespace radview::test {

enum class Variant { Book, Affine };
inline const char* name(Variant v) { return v == Variant::Book ? "book" : "affine"; }

// Every edge a boundary edge: the book's normal, or scipy's choice without a neighbour.
inline std::array<CrossBoundary, 3> boundaryEdges(const std::array<Vec3, 3>& V, Variant variant) {
  const Vec3 C = (V[0] + V[1] + V[2]) / 3.0;
  std::array<CrossBoundary, 3> edges;
  for (int k = 0; k < 3; ++k)
    edges[k].d = variant == Variant::Book ? bookCrossDirection(V[k], V[(k + 1) % 3], C)
                                          : affineCrossDirection(V[k], V[(k + 1) % 3], C, std::nullopt);
  return edges;
}

}  // namespace radview::test
