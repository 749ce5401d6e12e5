// Solution.render: radview render's picture, headless through EGL (or the final gather's, or the
// path tracer's), returned as a numpy array instead of written to a PNG.
#include "app/commands.h"
#include "app/display_flags.h"
#include "app/python/cli_arguments.h"
#include "app/python/module_parts.h"
#include "core/error.h"
#include "core/memory_budget.h"
#include "gl/egl_context.h"
#include "gl/mesh_renderer.h"
#include "interp/method_registry.h"

#include <pybind11/numpy.h>

#include <cmath>
#include <limits>

namespace py = pybind11;

namespace radview::python {

namespace {

constexpr const char* kFunction = "Solution.render";

py::array_t<uint8_t> displayArray(const Image& image) {
  py::array_t<uint8_t> out({py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(3)});
  uint8_t* o = out.mutable_data();
  for (size_t p = 0; p < size_t(image.width) * size_t(image.height); ++p)
    for (int c = 0; c < 3; ++c) *o++ = image.rgba[4 * p + c];
  return out;
}

// Linear radiosity, NaN where the pixel sees no surface (alpha 0).
py::array_t<float> linearArray(const LinearImage& image) {
  py::array_t<float> out({py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(3)});
  float* o = out.mutable_data();
  for (size_t p = 0; p < size_t(image.width) * size_t(image.height); ++p)
    for (int c = 0; c < 3; ++c)
      *o++ = image.rgba[4 * p + 3] > 0.0f ? image.rgba[4 * p + c] : std::numeric_limits<float>::quiet_NaN();
  return out;
}

py::array render(const Solution& solution, const py::kwargs& given) {
  py::kwargs options;
  bool linear = false;
  for (const auto& [key, value] : given) {
    if (py::str(key).cast<std::string>() == "linear")
      linear = value.cast<bool>();
    else
      options[key] = value;
  }
  DisplayOptions display;
  GatherOptions gather;
  std::string size = "640x480";
  CLI::App command;
  addDisplayOptions(command, display, pictureMethodNames());
  addGatherOptions(command, gather, "samples per pixel");
  command.add_option("--size", size);
  parseKeywordOptions(command, options, kFunction);
  const std::optional<RayTracer> tracer = rayTracerFromName(display.method);
  if (!tracer)
    for (const char* name : {"--gather-method", "--emitter-samples", "--spp", "--seed"})
      if (command.count(name) > 0) throw Error(std::string(name) + " needs method final-gather or path-trace");
  int width = 0, height = 0;
  parseSize(size, width, height);
  checkImageMemory(size, width, height, tracer ? kGatherBytesPerPixel : kComparisonBytesPerPixel, "the render");

  Image picture;
  LinearImage radiosity;
  {
    py::gil_scoped_release release;
    if (tracer) {
      const std::unique_ptr<ProgressiveImage> estimate =
          rayTracedEstimate(*solution.viewed, display, gather, width, height);
      while (estimate->samplesPerPixel() < gather.spp) estimate->addPasses(1);
      radiosity = estimate->image();
      if (!linear) picture = displayedGather(radiosity, std::exp2(display.exposure));
    } else {
      gl::EglContext context;
      gl::MeshRenderer renderer;
      drawHeadless(renderer, solution.viewed, display, width, height);
      if (linear)
        radiosity = renderer.readLinear();
      else
        picture = renderer.readDisplay();
    }
  }
  if (linear) return linearArray(radiosity);
  return displayArray(picture);
}

}  // namespace

void bindRendering(py::class_<Solution>& solution) {
  solution.def("render", &render, R"(render(**options) -> numpy.ndarray

The picture `radview render` would write, as an array: (height, width, 3) uint8 display colour,
or with linear=True (height, width, 3) float32 radiosity B, NaN where no surface is seen.
Options are render's, as keywords: method="clough-tocher", camera="front" or
"ex,ey,ez/tx,ty,tz", size=(640, 480) (the default), exposure, view="difference", edges=True,
tessellation="adaptive", ...; method="final-gather" or "path-trace" with spp, seed, gather_method.
GL methods draw through EGL headless (Mesa's llvmpipe where no GPU is present).)");
}

}  // namespace radview::python
