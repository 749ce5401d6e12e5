// radview.solve and radview.bench: the subcommands, with their options as keywords, returning
// what they made (a Solution, the trade table as arrays) besides the files they write.
#include "app/command_bench.h"
#include "app/command_solve.h"
#include "app/python/cli_arguments.h"
#include "app/python/module_parts.h"
#include "interp/method_registry.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <functional>

namespace py = pybind11;

namespace radview::python {

namespace {

py::object solve(const py::handle& scene, const py::object& out, const py::kwargs& options) {
  const std::string file = pathArgument(scene, "radview.solve");
  // Without out=, the solution goes to a temporary folder, removed once it is loaded back.
  py::object temporary = py::none();
  std::string written;
  if (out.is_none()) {
    temporary = py::module_::import("tempfile").attr("TemporaryDirectory")(py::arg("prefix") = "radview-solve-");
    written = py::str(temporary.attr("name")).cast<std::string>() + "/solution.glb";
  } else {
    written = pathArgument(out, "radview.solve");
  }
  SolveOptions solveOptions;
  CLI::App parent;
  CLI::App* command = addSolveCommand(parent, solveOptions);
  parseKeywordOptions(*command, options, "radview.solve", {file, "--out", written});
  {
    py::gil_scoped_release release;
    runSolve(solveOptions);
  }
  py::object solution = py::cast(load(py::str(written), py::kwargs()));
  if (!temporary.is_none()) temporary.attr("cleanup")();
  return solution;
}

// One column of the table: `field` of every row.
template <typename T>
py::array_t<T> column(const std::vector<TradeoffRow>& rows, const std::function<T(const TradeoffRow&)>& field) {
  py::array_t<T> out(static_cast<py::ssize_t>(rows.size()));
  for (size_t i = 0; i < rows.size(); ++i) out.mutable_data()[i] = field(rows[i]);
  return out;
}

// An error estimate's RMS and its 95 % interval, as three columns named `name`, `name`_low, `name`_high.
void addEstimate(py::dict& table, const std::vector<TradeoffRow>& rows, const std::string& name,
                 ErrorEstimate TradeoffRow::*estimate) {
  table[py::str(name)] = column<double>(rows, [&](const TradeoffRow& r) { return (r.*estimate).rms(); });
  table[py::str(name + "_low")] = column<double>(rows, [&](const TradeoffRow& r) { return (r.*estimate).rmsLow(); });
  table[py::str(name + "_high")] = column<double>(rows, [&](const TradeoffRow& r) { return (r.*estimate).rmsHigh(); });
}

py::dict bench(const py::handle& path, const py::kwargs& options) {
  const std::string file = pathArgument(path, "radview.bench");
  BenchOptions benchOptions;
  CLI::App parent;
  CLI::App* command = addBenchCommand(parent, benchOptions);
  parseKeywordOptions(*command, options, "radview.bench", {file});
  std::vector<TradeoffRow> rows;
  {
    py::gil_scoped_release release;
    rows = measureTrade(benchOptions);
  }
  py::dict table;
  std::vector<std::string> methods, settings, images;
  for (const TradeoffRow& r : rows) {
    methods.push_back(r.method);
    settings.push_back(r.setting);
    images.push_back(r.image);
  }
  table["method"] = py::array(py::cast(methods));
  table["setting"] = py::array(py::cast(settings));
  table["frame_ms"] = column<double>(rows, [](const TradeoffRow& r) { return r.frameMs; });
  table["triangles"] = column<int64_t>(rows, [](const TradeoffRow& r) { return int64_t(r.triangles); });
  table["rmse"] = column<double>(rows, [](const TradeoffRow& r) { return r.rmse; });
  table["max_error"] = column<double>(rows, [](const TradeoffRow& r) { return r.maxError; });
  table["display_rmse"] = column<double>(rows, [](const TradeoffRow& r) { return r.displayRmse; });
  table["display_max"] = column<double>(rows, [](const TradeoffRow& r) { return r.displayMax; });
  table["mach_bands"] = column<double>(rows, [](const TradeoffRow& r) { return r.machBands; });
  table["c0_kinks"] = column<double>(rows, [](const TradeoffRow& r) { return r.c0Kinks; });
  addEstimate(table, rows, "linear_error", &TradeoffRow::linearError);
  addEstimate(table, rows, "display_error", &TradeoffRow::displayError);
  addEstimate(table, rows, "mach_error", &TradeoffRow::machError);
  addEstimate(table, rows, "c0_kink_error", &TradeoffRow::c0KinkError);
  table["reference_noise_steps"] = column<double>(rows, [](const TradeoffRow& r) { return r.referenceNoiseSteps; });
  table["split"] = column<bool>(rows, [](const TradeoffRow& r) { return r.split; });
  addEstimate(table, rows, "solution_part", &TradeoffRow::solutionPart);
  addEstimate(table, rows, "reconstruction_part", &TradeoffRow::reconstructionPart);
  table["pareto"] = column<bool>(rows, [](const TradeoffRow& r) { return r.pareto; });
  table["image"] = py::array(py::cast(images));
  return table;
}

}  // namespace

void bindCommands(py::module_& m) {
  m.def("solve", &solve, py::arg("scene"), py::arg("out") = py::none(), R"(solve(scene, out=None, **options) -> Solution

`radview solve`: solves a glTF scene's radiosity and writes the solution to out (a .glb or
.gltf; without out, a temporary file), then loads it. Options are the command's, as keywords:
samples=64, unshot=0.0005, discontinuity_meshing=False, element_size=0.1, view=["file"], ...
The command's summary is printed as it prints it.)");
  m.def("bench", &bench, py::arg("file"), R"(bench(file, **options) -> dict

`radview bench`: measures every method and setting on one view against the reference, writes
out_dir (default "bench": bench.md, bench.csv, the images) and returns the table as a dict of
equal-length arrays, one entry per row: method, setting, frame_ms, triangles, display_error with
display_error_low and display_error_high (its 95 % interval, 8-bit display steps, the reference's
noise taken out), linear_error, mach_error, c0_kink_error (each with _low, _high), rmse,
max_error, display_rmse, display_max, mach_bands, c0_kinks, reference_noise_steps, split,
solution_part and reconstruction_part (with _low, _high; where split), pareto, image.
Options are the command's, as keywords: size=(128, 128), spp=168, reference="path-trace", ...)");
  m.def("methods", &pictureMethodNames,
        "methods() -> list\n\nThe method names render and sample take, the ray tracers' included.");
}

}  // namespace radview::python
