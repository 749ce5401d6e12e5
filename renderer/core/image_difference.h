#pragma once
// How far a render is from a reference, as the viewer shows it: the difference of displayed
// luminance (display units, 1/255 an 8-bit step), the number the difference view colours.
#include "core/image.h"

#include <cstddef>
#include <ostream>

namespace radview {

struct DisplayDifference {
  size_t pixels = 0;        // compared: covered in both images
  double rmse = 0.0;        // root mean square of (render - reference)
  double meanSigned = 0.0;  // mean of (render - reference): a bias, e.g. an exposure mismatch
  double maxAbs = 0.0;      // the largest |render - reference|
};

// Compares a linear render (alpha > 0 where covered, readLinear) shown at `exposureScale` with
// a reference image shown the same way (a linear reference through the same exposure and tone
// map, a display one as it is), over the pixels covered in both with finite values. Throws
// Error naming the reference's path if the sizes differ.
DisplayDifference displayDifference(const LinearImage& render, const ReferenceImage& reference, double exposureScale);

std::ostream& operator<<(std::ostream& os, const DisplayDifference& d);

}  // namespace radview
