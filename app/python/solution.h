#pragma once
// radview.Solution: a file opened as the viewer opens it (solve/viewed_file.h), its nodal arrays
// seen from numpy without copies. The module's other functions take it.
#include "solve/viewed_file.h"

#include <pybind11/pybind11.h>

#include <memory>
#include <string>

namespace radview::python {

struct Solution {
  std::shared_ptr<const ViewedFile> viewed;
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
