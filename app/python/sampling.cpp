// Solution.sample: radview sample's interpolants at numpy arrays of points, into numpy arrays,
// on every core with the GIL released (interp/point_sampling.h is the core it shares with the
// command line).
#include "app/commands.h"
#include "app/python/module_parts.h"
#include "core/camera.h"
#include "core/error.h"
#include "core/limits.h"
#include "core/memory_budget.h"
#include "core/parallel_for.h"
#include "interp/method_registry.h"
#include "interp/point_sampling.h"
#include "scene/camera_presets.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace py = pybind11;

namespace radview::python {

namespace {

constexpr const char* kFunction = "Solution.sample";

// `value` as a C-ordered float64 array of shape (N, columns) (a single row may be given as
// (columns,)); refuses other shapes and non-numeric dtypes, naming the argument.
py::array_t<double> floatRows(const py::handle& value, py::ssize_t columns, const std::string& name) {
  const py::array a = py::array::ensure(value);
  if (!a) throw py::type_error(std::string(kFunction) + ": " + name + " must be an array of numbers");
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::type_error(std::string(kFunction) + ": " + name + " has dtype " + std::string(py::str(a.dtype())) +
                         "; expected floating-point numbers");
  const bool oneRow = a.ndim() == 1 && a.shape(0) == columns;
  if (!oneRow && !(a.ndim() == 2 && a.shape(1) == columns)) {
    std::string shape = "(";
    for (py::ssize_t d = 0; d < a.ndim(); ++d) shape += (d ? ", " : "") + std::to_string(a.shape(d));
    throw py::value_error(std::string(kFunction) + ": " + name + " has shape " + shape + (a.ndim() == 1 ? ",)" : ")") +
                          "; expected (N, " + std::to_string(columns) + ")");
  }
  auto rows = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  if (oneRow) rows = rows.reshape({py::ssize_t(1), columns});
  const double* v = rows.data();
  for (py::ssize_t i = 0; i < rows.size(); ++i)
    if (!std::isfinite(v[i]))
      throw py::value_error(std::string(kFunction) + ": " + name + " row " + std::to_string(i / columns) +
                            " holds a number that is not finite");
  return rows;
}

// The element indices, each checked against the mesh.
std::vector<uint32_t> elementIndices(const py::handle& value, size_t count, size_t elementCount) {
  const py::array a = py::array::ensure(value);
  if (!a || (a.dtype().kind() != 'i' && a.dtype().kind() != 'u'))
    throw py::type_error(std::string(kFunction) + ": element must be an array of integers");
  const auto e =
      py::array_t<int64_t, py::array::c_style | py::array::forcecast>::ensure(py::array(a).reshape({a.size()}));
  if (size_t(e.size()) != count)
    throw py::value_error(std::string(kFunction) + ": element has " + std::to_string(e.size()) +
                          " entries and barycentric " + std::to_string(count) + " rows");
  std::vector<uint32_t> out(count);
  for (size_t i = 0; i < count; ++i) {
    const int64_t k = e.data()[i];
    if (k < 0 || uint64_t(k) >= elementCount)
      throw py::value_error(std::string(kFunction) + ": element row " + std::to_string(i) + ": no element " +
                            std::to_string(k) + " (the mesh has " + std::to_string(elementCount) +
                            " elements, numbered from 0)");
    out[i] = uint32_t(k);
  }
  return out;
}

// The cached interpolant when it was built with the same settings (`key`), else a new one, kept.
std::shared_ptr<const Interpolant> interpolantFor(const Solution& solution, Method method,
                                                  const InterpolantOptions& options, const std::string& key) {
  SamplingCache& cache = *solution.sampling;
  const std::lock_guard<std::mutex> lock(cache.mutex);
  if (!cache.interpolant || cache.interpolantKey != key) {
    cache.interpolant = nullptr;  // the old one's memory is free before the new one is built
    cache.interpolant = makeInterpolant(solution.mesh(), method, options);
    cache.interpolantKey = key;
  }
  return cache.interpolant;
}

const SurfaceLocator& locatorFor(const Solution& solution) {
  SamplingCache& cache = *solution.sampling;
  const std::lock_guard<std::mutex> lock(cache.mutex);
  if (!cache.locator) cache.locator = std::make_unique<SurfaceLocator>(solution.mesh());
  return *cache.locator;
}

py::dict sample(const Solution& solution, const py::object& points, const py::object& element,
                const py::object& barycentric, const std::string& methodName, const std::string& diagonal,
                const std::string& variant, const std::string& smoothing, bool estimateGradients, bool standardError,
                std::optional<double> maxDistanceGiven, const std::string& cameraSpec, const std::string& size) {
  const RadiosityMesh& mesh = solution.mesh();
  const bool byElement = points.is_none();
  if (byElement ? element.is_none() || barycentric.is_none() : !element.is_none() || !barycentric.is_none())
    throw py::type_error(std::string(kFunction) + ": give points, or element and barycentric, not both");
  const Method method = methodFromName(methodName);
  InterpolantOptions options = interpolantOptionsFromNames(diagonal, variant, smoothing, estimateGradients);
  if (methodInfo(method).viewDependent) {
    int width = 0, height = 0;
    parseSize(size, width, height);
    const Camera camera = cameraFromSpec(cameraSpec, mesh.bounds(), solution.viewed->file.scene.cameras);
    options.view = ScreenView{camera.clipFromWorld(double(width) / height), Vec2(width, height)};
  }
  // The settings the interpolant is built with, as one key for the cache.
  const std::string settingsKey = methodName + "|" + diagonal + "|" + variant + "|" + smoothing + "|" +
                                  (estimateGradients ? "e" : "s") +
                                  (methodInfo(method).viewDependent ? "|" + cameraSpec + "|" + size : "");
  if (standardError && !mesh.hasStandardErrors)
    throw Error(solution.viewed->file.path,
                "has no standard errors for standard_error=True (its solver did not estimate them)");
  if (maxDistanceGiven && !(*maxDistanceGiven >= 0.0))
    throw py::value_error(std::string(kFunction) + ": max_distance must be a number >= 0");
  const double maxDistance = maxDistanceGiven ? *maxDistanceGiven : 1e-3 * mesh.bounds().diagonal();

  const py::array_t<double> rows = floatRows(byElement ? barycentric : points, 3, byElement ? "barycentric" : "points");
  const size_t n = size_t(rows.shape(0));
  checkLimit(kFunction, n, std::numeric_limits<uint32_t>::max(), "points in one call");
  // The output arrays (element, x, distance, B, gradient, standard error) and the evaluation order.
  constexpr uint64_t kBytesPerPoint = 4 + 8 * (3 + 1 + 3 + 9 + 3) + 4;
  checkMemory(kFunction, "the samples of " + std::to_string(n) + " points", n * kBytesPerPoint);
  std::vector<uint32_t> elements;
  if (byElement) {
    elements = elementIndices(element, n, mesh.elements.size());
    // float32 coordinates sum to 1 only within float32's rounding.
    const double tolerance = py::array::ensure(barycentric).dtype().itemsize() == 4 ? 1e-6 : 1e-9;
    for (size_t i = 0; i < n; ++i) {
      const double* b = rows.data() + 3 * i;
      if (std::abs(b[0] + b[1] + b[2] - 1.0) > tolerance)
        throw py::value_error(std::string(kFunction) + ": barycentric row " + std::to_string(i) +
                              ": coordinates must sum to 1");
    }
  }

  py::array_t<uint32_t> elementOut(static_cast<py::ssize_t>(n));
  py::array_t<double> x({py::ssize_t(n), py::ssize_t(3)}), distance(static_cast<py::ssize_t>(n)),
      B({py::ssize_t(n), py::ssize_t(3)});
  py::array_t<double> gradient({py::ssize_t(n), py::ssize_t(3), py::ssize_t(3)});
  py::array_t<double> errorOut({py::ssize_t(standardError ? n : 0), py::ssize_t(3)});
  uint32_t* e = elementOut.mutable_data();
  double *xo = x.mutable_data(), *d = distance.mutable_data(), *b = B.mutable_data(), *g = gradient.mutable_data();
  double* se = errorOut.mutable_data();
  const double* v = rows.data();
  {
    py::gil_scoped_release release;
    // Placed into the output arrays on every core, then evaluated there: the points are not kept
    // twice. A point off every surface is reported once all are placed.
    const SurfaceLocator* locator = byElement ? nullptr : &locatorFor(solution);
    forEachPlacedPoint(
        mesh, n,
        [&](size_t i) {
          return PointQuery{byElement ? elements[i] : PointQuery::kWorldPoint,
                            Vec3(v[3 * i], v[3 * i + 1], v[3 * i + 2])};
        },
        maxDistance,
        [&](size_t i, const SurfacePoint& p) {
          e[i] = p.element;
          d[i] = p.distance;
          for (int c = 0; c < 3; ++c) xo[3 * i + c] = p.x[c];
        },
        locator);
    for (size_t i = 0; i < n; ++i)
      if (d[i] > maxDistance)
        throw Error("points row " + std::to_string(i) + " is off every surface: the nearest element (" +
                    std::to_string(e[i]) + ") is " + std::to_string(d[i]) + " away, more than max_distance " +
                    std::to_string(maxDistance));
    const std::shared_ptr<const Interpolant> interpolant = interpolantFor(solution, method, options, settingsKey);
    std::optional<StandardErrorField> errors;
    if (standardError) errors.emplace(mesh, options);
    const std::vector<uint32_t> order = orderByElement(e, n, mesh.elements.size());
    parallelFor(n, [&](size_t rank) {
      const size_t i = order[rank];
      const SurfacePoint p{e[i], Vec3(xo[3 * i], xo[3 * i + 1], xo[3 * i + 2]), d[i]};
      const Sample s = interpolant->evaluate(p.element, p.x);
      for (int c = 0; c < 3; ++c) {
        b[3 * i + c] = s.B[c];
        for (int k = 0; k < 3; ++k) g[9 * i + 3 * c + k] = s.gradient[c][k];
      }
      if (errors) {
        const Rgb error = errors->at(p);
        for (int c = 0; c < 3; ++c) se[3 * i + c] = error[c];
      }
    });
  }
  py::dict out;
  out["element"] = elementOut;
  out["x"] = x;
  out["distance"] = distance;
  out["B"] = B;
  out["gradient"] = gradient;
  if (standardError) out["standard_error"] = errorOut;
  return out;
}

}  // namespace

void bindSampling(py::class_<Solution>& solution) {
  solution.def(
      "clear_cache",
      [](const Solution& s) {
        const std::lock_guard<std::mutex> lock(s.sampling->mutex);
        s.sampling->locator = nullptr;
        s.sampling->interpolant = nullptr;
        s.sampling->interpolantKey.clear();
      },
      R"(clear_cache()

Frees what sample() keeps for its next call: the point locator and the last method's set-up
(Clough-Tocher's is about 900 bytes a triangle, 1.5 GB at 10^6 elements).)");
  solution.def("sample", &sample, py::arg("points") = py::none(), py::kw_only(), py::arg("element") = py::none(),
               py::arg("barycentric") = py::none(), py::arg("method") = "clough-tocher", py::arg("diagonal") = "02",
               py::arg("variant") = "affine", py::arg("smoothing") = "auto", py::arg("estimate_gradients") = false,
               py::arg("standard_error") = false, py::arg("max_distance") = py::none(), py::arg("camera") = "",
               py::arg("size") = "1024x768",
               R"(sample(points=None, *, element=None, barycentric=None, method="clough-tocher", ...) -> dict

The reconstructed radiosity and its surface gradient at points, as `radview sample` computes them
(the CPU reference of each interpolant), on every core.

points: (N, 3) world positions, each placed at the nearest point of the nearest element (farther
  than max_distance, default 1e-3 of the bounds' diagonal, is an error); or
element (N,) integers and barycentric (N, 3) coordinates in each element's first three corners.
method: any of radview.methods(); diagonal ("02"/"13", gouraud), variant ("affine"/"book",
  clough-tocher), smoothing ("auto" or lambda, thin-plate), estimate_gradients, and camera and
  size (scanline-gouraud's view) as the command line's options.
standard_error=True adds the solver's standard error of B, interpolated linearly.

The point locator and the method's set-up (its patches, gradients, smoothing) are kept with the
Solution for the next call with the same settings; clear_cache() frees them.

Returns a dict of arrays: element (N,) uint32, x (N, 3) the surface points, distance (N,),
B (N, 3), gradient (N, 3, 3) ([i, channel] is grad B of that channel), and standard_error (N, 3)
when asked. Raises TypeError or ValueError for arrays of the wrong shape or dtype, or holding NaN;
radview.Error for a point off every surface or an option radview refuses.)");
}

}  // namespace radview::python
