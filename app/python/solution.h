#pragma once
// radview.Solution: a file opened as the viewer opens it (solve/viewed_file.h), its nodal arrays
// seen from numpy without copies. The module's other functions take it.
#include "interp/interpolant.h"
#include "interp/surface_locator.h"
#include "solve/viewed_file.h"

#include <pybind11/pybind11.h>

#include <memory>
#include <mutex>
#include <string>

namespace radview::python {

// What Solution.sample builds from the mesh, kept for the next call: the point locator, and
// the last interpolant with the settings it was built for (Clough-Tocher's set-up takes seconds
// at 10^6 elements, the evaluation of a million points a fraction of that). Built under the lock;
// the mesh never changes, so what is built stays valid.
struct SamplingCache {
  std::mutex mutex;
  std::unique_ptr<SurfaceLocator> locator;
  std::string interpolantKey;
  std::shared_ptr<const Interpolant> interpolant;
};

struct Solution {
  std::shared_ptr<const ViewedFile> viewed;
  std::shared_ptr<SamplingCache> sampling = std::make_shared<SamplingCache>();
  const RadiosityMesh& mesh() const { return viewed->mesh; }
};

// A path argument: a str, an os.PathLike, or an open file object (its name). Throws
// pybind11::value_error for a closed file, pybind11::type_error for anything else.
std::string pathArgument(const pybind11::handle& path, const std::string& function);

// radview.load(path, **options): opens the file with the command line's options for opening one
// (--element-size, the import options, --direct-only and the solve's). Releases the GIL.
Solution load(const pybind11::handle& path, const pybind11::kwargs& options);

// Registers radview.Solution, its arrays, and radview.load. Returns the class for the other
// files to add their methods to.
pybind11::class_<Solution> bindSolution(pybind11::module_& module);

}  // namespace radview::python
