#pragma once
// How far a rendered image is from the reference, as `radview bench` reports it: on the pixels
// whose surface point and its four neighbours' lie on one plane, in radiometric luminance.
#include "core/image.h"
#include "mesh/radiosity_mesh.h"

#include <cstdint>
#include <vector>

namespace radview {

// Pixels that see an element (elementAt[p] >= 0, row 0 the top row) whose plane their four
// neighbours see too: no silhouette or crease, where the reference antialiases (it averages
// the surfaces a pixel covers) and the GL renderer does not, a difference of sampling rather
// than of interpolation. The image border is never interior.
std::vector<char> interiorPixels(const RadiosityMesh& mesh, const std::vector<int32_t>& elementAt, int width,
                                 int height);

struct LuminanceError {
  double rmse = 0.0, max = 0.0;  // of Y(B) - Y(B_reference), Rec. 709 weights, linear
  size_t pixels = 0;             // compared: covered in both (alpha > 1/2), finite
};

// Over the pixels both images cover; the two must be of one size.
LuminanceError luminanceError(const LinearImage& image, const LinearImage& reference);

// The median (the mean of the middle two for an even count); 0 for none.
double median(std::vector<double> values);

}  // namespace radview
