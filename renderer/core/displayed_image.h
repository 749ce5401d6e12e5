#pragma once
// A linear radiosity image as the GL display pass shows it (shaders/tonemap.frag), on the CPU:
// for images made without OpenGL, such as the final gather's.
#include "core/image.h"
#include "core/types.h"

namespace radview {

// Exposure and sRGB (core/display_transform.h) where a surface is seen, `background` (a
// display colour) where none is; a pixel partly covered (alpha, the gather's antialiasing)
// blends the two by its coverage. 8 bits per channel, rounded; alpha 255.
Image displayedImage(const LinearImage& linear, double exposureScale, const Rgb& background);

}  // namespace radview
