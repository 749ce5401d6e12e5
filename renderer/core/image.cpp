#include "core/image.h"

#include "core/atomic_file.h"
#include "core/error.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

namespace radview {

namespace {

// RGBA pixels of type T (UINT8 or FLOAT as `type`) to any format OpenImageIO encodes in memory
// (the extension of `path` picks it), then to the file through writeFileAtomically: OpenImageIO
// writing the file itself would leave a truncated one behind when a write fails.
template <typename T>
void writeRgba(const std::string& path, int width, int height, OIIO::TypeDesc type, const std::vector<T>& rgba) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw Error(path, "cannot write an image here: " + OIIO::geterror() + "; no file was written");
  if (!out->supports("ioproxy"))
    throw Error(path, std::string("OpenImageIO cannot encode ") + out->format_name() +
                          " images in memory, which radview's safe writes need; no file was written");
  std::vector<unsigned char> encoded;
  OIIO::Filesystem::IOVecOutput memory(encoded);
  OIIO::ImageSpec spec(width, height, 4, type);
  if (!out->set_ioproxy(&memory) || !out->open(path, spec) || !out->write_image(type, rgba.data()) || !out->close())
    throw Error(path, "cannot encode the image: " + out->geterror() + "; no file was written");
  writeFileAtomically(path, std::string(encoded.begin(), encoded.end()));
}

// Any file OpenImageIO reads as RGBA pixels of type T: gray, gray+alpha, RGB or RGBA, alpha
// `opaque` where the file has none. Returns the file's own spec (its pixel type included).
template <typename T>
OIIO::ImageSpec readRgba(const std::string& path, OIIO::TypeDesc type, T opaque, int& width, int& height,
                         std::vector<T>& rgba) {
  OIIO::ImageBuf buffer(path);
  if (!buffer.read(0, 0, true, type)) throw Error(path, "cannot read image: " + buffer.geterror());
  const OIIO::ImageSpec& spec = buffer.spec();
  if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1) throw Error(path, "the image has no pixels");
  width = spec.width;
  height = spec.height;
  rgba.assign(size_t(width) * height * 4, opaque);
  const int channels = spec.nchannels;
  std::vector<T> pixels(size_t(width) * height * channels);
  buffer.get_pixels(OIIO::ROI::All(), type, pixels.data());
  const bool gray = channels < 3;
  const int alpha = channels == 2 ? 1 : channels >= 4 ? 3 : -1;
  for (size_t i = 0; i < size_t(width) * height; ++i) {
    const T* p = &pixels[i * channels];
    for (int c = 0; c < 3; ++c) rgba[i * 4 + c] = p[gray ? 0 : c];
    if (alpha >= 0) rgba[i * 4 + 3] = p[alpha];
  }
  return buffer.nativespec();
}

}  // namespace

void writePng(const Image& image, const std::string& path) {
  writeRgba(path, image.width, image.height, OIIO::TypeDesc::UINT8, image.rgba);
}

void writeLinearImage(const LinearImage& image, const std::string& path) {
  writeRgba(path, image.width, image.height, OIIO::TypeDesc::FLOAT, image.rgba);
}

Image readImage(const std::string& path) {
  Image image;
  readRgba<uint8_t>(path, OIIO::TypeDesc::UINT8, 255, image.width, image.height, image.rgba);
  return image;
}

ReferenceImage readReferenceImage(const std::string& path) {
  ReferenceImage reference;
  reference.path = path;
  LinearImage& image = reference.pixels;
  // The file's own pixel type says what it holds: floats radiosity, integers display colour.
  reference.linear = readRgba<float>(path, OIIO::TypeDesc::FLOAT, 1.0f, image.width, image.height, image.rgba)
                         .format.is_floating_point();
  return reference;
}

}  // namespace radview
