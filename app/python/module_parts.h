#pragma once
// The parts of the Python module, each registered by its own file (module.cpp calls them).
#include "app/python/solution.h"

#include <pybind11/pybind11.h>

namespace radview::python {

void bindSampling(pybind11::class_<Solution>& solution);   // sampling.cpp: Solution.sample
void bindRendering(pybind11::class_<Solution>& solution);  // rendering.cpp: Solution.render
void bindCommands(pybind11::module_& module);              // commands.cpp: radview.solve, radview.bench

}  // namespace radview::python
