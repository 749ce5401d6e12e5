#pragma once
// Python keyword arguments as the command line's options, so that every function of the module
// takes exactly the options of its subcommand, checked and refused with the same messages:
// samples=64 is --samples 64, discontinuity_meshing=False is --no-discontinuity-meshing,
// size=(640, 480) is --size 640x480, view=["front", "file"] is --view front --view file.
#include <pybind11/pybind11.h>
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace radview::python {

// Parses `options` with `command`'s options, after `leading` (positional arguments, or options
// the caller sets). `function` names the caller in errors ("radview.load"). Throws Error for an
// option the command does not have or a value it refuses.
void parseKeywordOptions(CLI::App& command, const pybind11::kwargs& options, const std::string& function,
                         const std::vector<std::string>& leading = {});

}  // namespace radview::python
