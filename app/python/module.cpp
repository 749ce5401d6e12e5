// `import radview`: radview's solutions, interpolants, renderer and commands from Python, over
// numpy arrays (README "Python").
#include "app/python/module_parts.h"
#include "core/error.h"

#include <pybind11/pybind11.h>

namespace py = pybind11;

PYBIND11_MODULE(radview, m) {
  m.doc() = R"(radview: a viewer for radiosity solutions (Cohen & Wallace, Radiosity and Realistic
Image Synthesis, section 9.2-9.3), from Python.

  solution = radview.load("cornell_box_solved.glb")
  solution.B                      # (nodes, 3) nodal radiosity, a numpy view
  s = solution.sample(points, method="clough-tocher")
  image = solution.render(method="gouraud", size=(320, 240))
  table = radview.bench("cornell_box_solved.glb", size=(64, 64))

Errors radview refuses raise radview.Error, with the command line's message.)";
  py::register_exception<radview::Error>(m, "Error", PyExc_RuntimeError);
  // Each docstring opens with its signature as a user writes the call (keywords and defaults);
  // pybind11's generated one would name C++ types.
  py::options options;
  options.disable_function_signatures();
  py::class_<radview::python::Solution> solution = radview::python::bindSolution(m);
  radview::python::bindSampling(solution);
  radview::python::bindRendering(solution);
  radview::python::bindCommands(m);
}
