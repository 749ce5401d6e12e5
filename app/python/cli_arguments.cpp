#include "app/python/cli_arguments.h"

#include "core/error.h"

#include <algorithm>
#include <vector>

namespace py = pybind11;

namespace radview::python {

namespace {

// A value as the command line writes it: a float as the shortest text that reads back as it.
std::string optionText(const py::handle& value) {
  if (py::isinstance<py::float_>(value)) return py::str(py::repr(value));
  return py::str(value);
}

bool hasOption(CLI::App& command, const std::string& name) {
  try {
    command.get_option(name);
    return true;
  } catch (const CLI::OptionNotFound&) {
    return false;
  }
}

}  // namespace

void parseKeywordOptions(CLI::App& command, const py::kwargs& options, const std::string& function,
                         const std::vector<std::string>& leading) {
  std::vector<std::string> arguments = leading;
  for (const auto& [key, value] : options) {
    std::string name = "--" + py::str(key).cast<std::string>();
    std::replace(name.begin(), name.end(), '_', '-');
    if (!hasOption(command, name))
      throw Error(function + ": no option " + py::str(key).cast<std::string>() + " (" + name + ")");
    if (py::isinstance<py::bool_>(value)) {
      if (value.cast<bool>()) {
        arguments.push_back(name);
      } else {
        const std::string negative = "--no-" + name.substr(2);
        if (hasOption(command, negative)) arguments.push_back(negative);
      }
    } else if (name == "--size" || name == "--view-size") {
      if (py::isinstance<py::tuple>(value) || py::isinstance<py::list>(value)) {
        const py::sequence sides = py::reinterpret_borrow<py::sequence>(value);
        if (sides.size() != 2) throw Error(function + ": " + name + " takes (width, height)");
        arguments.push_back(name);
        arguments.push_back(optionText(sides[0]) + "x" + optionText(sides[1]));
      } else {
        arguments.push_back(name);
        arguments.push_back(optionText(value));
      }
    } else if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
      for (const py::handle item : value) {
        arguments.push_back(name);
        arguments.push_back(optionText(item));
      }
    } else if (!value.is_none()) {
      arguments.push_back(name);
      arguments.push_back(optionText(value));
    }
  }
  std::reverse(arguments.begin(), arguments.end());  // CLI11 takes them last first
  try {
    command.parse(arguments);
  } catch (const CLI::ParseError& e) {
    throw Error(function + ": " + e.what());
  }
}

}  // namespace radview::python
