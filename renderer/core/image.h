#pragma once
// 8-bit RGBA images as rendered, and their PNG files (OpenImageIO).
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

void writePng(const Image& image, const std::string& path);  // throws Error naming the path
Image readImage(const std::string& path);                     // any format OpenImageIO reads, as RGBA8

}  // namespace radview
