#include "core/image.h"

#include "core/error.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

namespace radview {

void writePng(const Image& image, const std::string& path) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw Error(path, "cannot write an image here: " + OIIO::geterror());
  OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
  if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::UINT8, image.rgba.data()) || !out->close())
    throw Error(path, "cannot write image: " + out->geterror());
}

Image readImage(const std::string& path) {
  OIIO::ImageBuf buffer(path);
  if (!buffer.read(0, 0, true, OIIO::TypeDesc::UINT8)) throw Error(path, "cannot read image: " + buffer.geterror());
  const OIIO::ImageSpec& spec = buffer.spec();
  Image image;
  image.width = spec.width;
  image.height = spec.height;
  image.rgba.assign(size_t(spec.width) * spec.height * 4, 255);
  // Gray, gray+alpha, RGB or RGBA files all come back as RGBA.
  const int channels = spec.nchannels;
  std::vector<uint8_t> pixels(size_t(spec.width) * spec.height * channels);
  buffer.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, pixels.data());
  const bool gray = channels < 3;
  const int alpha = channels == 2 ? 1 : channels >= 4 ? 3 : -1;
  for (size_t i = 0; i < size_t(spec.width) * spec.height; ++i) {
    const uint8_t* p = &pixels[i * channels];
    for (int c = 0; c < 3; ++c) image.rgba[i * 4 + c] = p[gray ? 0 : c];
    image.rgba[i * 4 + 3] = alpha < 0 ? 255 : p[alpha];
  }
  return image;
}

void writeLinearImage(const LinearImage& image, const std::string& path) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw Error(path, "cannot write an image here: " + OIIO::geterror());
  OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT);
  if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, image.rgba.data()) || !out->close())
    throw Error(path, "cannot write image: " + out->geterror());
}

ReferenceImage readReferenceImage(const std::string& path) {
  OIIO::ImageBuf buffer(path);
  if (!buffer.read(0, 0, true, OIIO::TypeDesc::FLOAT)) throw Error(path, "cannot read image: " + buffer.geterror());
  const OIIO::ImageSpec& spec = buffer.spec();
  if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1) throw Error(path, "the image has no pixels");
  ReferenceImage reference;
  reference.path = path;
  // The file's own pixel type says what it holds: floats are radiance-like, integers display.
  OIIO::ImageSpec fileSpec;
  if (auto in = OIIO::ImageInput::open(path)) {
    fileSpec = in->spec();
    in->close();
  }
  reference.linear = fileSpec.format.is_floating_point();
  LinearImage& image = reference.pixels;
  image.width = spec.width;
  image.height = spec.height;
  image.rgba.assign(size_t(spec.width) * spec.height * 4, 1.0f);
  const int channels = spec.nchannels;
  std::vector<float> pixels(size_t(spec.width) * spec.height * channels);
  buffer.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, pixels.data());
  const bool gray = channels < 3;
  const int alpha = channels == 2 ? 1 : channels >= 4 ? 3 : -1;
  for (size_t i = 0; i < size_t(spec.width) * spec.height; ++i) {
    const float* p = &pixels[i * channels];
    for (int c = 0; c < 3; ++c) image.rgba[i * 4 + c] = p[gray ? 0 : c];
    if (alpha >= 0) image.rgba[i * 4 + 3] = p[alpha];
  }
  return reference;
}

}  // namespace radview
