#pragma once
// Images as rendered: 8-bit display RGBA and linear radiosity, their files (OpenImageIO), and
// reference images to compare renders against.
#include <cstdint>
#include <string>
#include <vector>

namespace radview {

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // row 0 is the top row
};

// Linear (pre-tone-map) radiosity per pixel, as rendered; alpha 0 where no surface is seen.
struct LinearImage {
  int width = 0, height = 0;
  std::vector<float> rgba;  // row 0 is the top row
};

// Image files are written whole or not at all (core/atomic_file.h): a failed write throws Error
// naming the path and leaves any file that was there unchanged.
void writePng(const Image& image, const std::string& path);
Image readImage(const std::string& path);  // any format OpenImageIO reads, as RGBA8
// Linear radiosity as a float file (OpenEXR for .exr; any float format OpenImageIO writes),
// alpha kept as coverage. Throws Error naming the path.
void writeLinearImage(const LinearImage& image, const std::string& path);

// An image a render is compared with: linear radiosity (a float file: EXR, HDR, PFM, float
// TIFF), shown through the same exposure and tone map as the render; or display colour (an 8-
// or 16-bit file such as a PNG screenshot), compared as it is, values in [0, 1].
struct ReferenceImage {
  LinearImage pixels;  // RGBA; alpha 1 where the file has no alpha
  bool linear = false;
  std::string path;
};
// Throws Error naming the path for a file OpenImageIO cannot read or one with no pixels.
ReferenceImage readReferenceImage(const std::string& path);

}  // namespace radview
