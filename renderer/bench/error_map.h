#pragma once
// Where a bench row loses: its signed difference from the reference at every compared pixel,
// as a linear image (for a user's own analysis) and as a false-colour picture on the diverging
// scale of the viewer's difference view (shaders/false_colour.frag): blue where the row is
// darker than the reference, white where they agree, red where it is brighter.
#include "core/image.h"

#include <cstdint>
#include <vector>

namespace radview {

// row - reference in linear RGB at the compared pixels (alpha 1), 0 elsewhere (alpha 0).
LinearImage signedDifference(const LinearImage& row, const LinearImage& reference, const std::vector<uint32_t>& pixels);

// The difference of displayed luminance (exposure, tone map, Rec. 709 weights; 8-bit steps) at
// the compared pixels, +-`scaleSteps` at the ends of the scale; other pixels mid grey.
Image differenceMap(const LinearImage& row, const LinearImage& reference, const std::vector<uint32_t>& pixels,
                    double exposureScale, double scaleSteps);

// Where the reference is noisy: `values[i]` (>= 0, display steps) at pixel pixels[i], on the
// red half of the same scale (white 0, red `scaleSteps` and above); other pixels mid grey.
Image magnitudeMap(int width, int height, const std::vector<uint32_t>& pixels, const std::vector<double>& values,
                   double scaleSteps);

}  // namespace radview
