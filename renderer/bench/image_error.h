#pragma once
// Where `radview bench` compares a rendered image with its reference: the pixels whose surface
// point and its four neighbours' lie on one plane (bench/bench_reference.h measures there).
#include "core/image.h"
#include "mesh/radiosity_mesh.h"

#include <cstdint>
#include <vector>

namespace radview {

// Whether two elements lie in one plane, to the precision of the positions of a solution file;
// `diagonal` is mesh.bounds().diagonal(), computed once by the caller (it visits every node).
bool coplanarElements(const RadiosityMesh& mesh, size_t a, size_t b, double diagonal);

// Pixels that see an element (elementAt[p] >= 0, row 0 the top row) whose plane their four
// neighbours see too: no silhouette or crease, where the reference antialiases (it averages
// the surfaces a pixel covers) and the GL renderer does not, a difference of sampling rather
// than of interpolation. The image border is never interior.
std::vector<char> interiorPixels(const RadiosityMesh& mesh, const std::vector<int32_t>& elementAt, int width,
                                 int height);

// The median (the mean of the middle two for an even count); 0 for none.
double median(std::vector<double> values);

}  // namespace radview
