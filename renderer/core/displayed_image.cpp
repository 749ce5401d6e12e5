#include "core/displayed_image.h"

#include "core/display_transform.h"

#include <cmath>

namespace radview {

Image displayedImage(const LinearImage& linear, double exposureScale, const Rgb& background) {
  Image image{linear.width, linear.height, std::vector<uint8_t>(linear.rgba.size())};
  for (size_t i = 0; i < linear.rgba.size() / 4; ++i) {
    const float* p = &linear.rgba[4 * i];
    const double alpha = p[3];
    const Rgb shown = alpha > 0.0 ? displayed(Rgb(p[0], p[1], p[2]), exposureScale) : Rgb(0.0);
    const Rgb blended = alpha * shown + (1.0 - alpha) * background;
    for (int c = 0; c < 3; ++c) image.rgba[4 * i + size_t(c)] = uint8_t(std::lround(255.0 * blended[c]));
    image.rgba[4 * i + 3] = 255;
  }
  return image;
}

}  // namespace radview
