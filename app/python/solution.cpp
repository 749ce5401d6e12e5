#include "app/python/solution.h"

#include "app/import_flags.h"
#include "app/python/cli_arguments.h"
#include "app/scene_light.h"
#include "app/solve_progress_bar.h"
#include "core/error.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstddef>
#include <vector>

namespace py = pybind11;

namespace radview::python {

namespace {

// A read-only numpy view of `count` rows `rowBytes` apart starting at `first`, each row of
// `inner` doubles (or `inner` shape with its strides); `owner` is kept alive while it lives.
py::array readOnlyView(const py::dtype& dtype, std::vector<py::ssize_t> shape, std::vector<py::ssize_t> strides,
                       const void* first, const py::handle& owner) {
  py::array view(dtype, std::move(shape), std::move(strides), first, owner);
  py::detail::array_proxy(view.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return view;
}

// The nodes' field at `offset` (bytes into Node) as an (N, 3) array of float64, or (N, 3, 3) for
// the gradients: strided over the nodes, no copy.
py::array nodeField(const py::object& self, size_t offset, bool matrix) {
  const Solution& s = self.cast<const Solution&>();
  const std::vector<Node>& nodes = s.mesh().nodes;
  const auto* first = reinterpret_cast<const char*>(nodes.data()) + (nodes.empty() ? 0 : offset);
  const py::ssize_t n = py::ssize_t(nodes.size()), row = sizeof(Node), d = sizeof(double);
  if (matrix) return readOnlyView(py::dtype::of<double>(), {n, 3, 3}, {row, py::ssize_t(sizeof(Vec3)), d}, first, self);
  return readOnlyView(py::dtype::of<double>(), {n, 3}, {row, d}, first, self);
}

// The elements' corner lists, flattened, and where each element's begins (CSR).
py::tuple elementCornerLists(const Solution& s) {
  const std::vector<Element>& elements = s.mesh().elements;
  py::array_t<int64_t> offsets(static_cast<py::ssize_t>(elements.size() + 1));
  auto o = offsets.mutable_unchecked<1>();
  size_t total = 0;
  for (size_t i = 0; i < elements.size(); ++i) {
    o(py::ssize_t(i)) = int64_t(total);
    total += elements[i].corners.size();
  }
  o(py::ssize_t(elements.size())) = int64_t(total);
  py::array_t<uint32_t> corners(static_cast<py::ssize_t>(total));
  uint32_t* out = corners.mutable_data();
  for (const Element& e : elements) out = std::copy(e.corners.begin(), e.corners.end(), out);
  return py::make_tuple(corners, offsets);
}

// (M, k) corner indices when every element has k corners.
py::array_t<uint32_t> uniformElements(const Solution& s) {
  const std::vector<Element>& elements = s.mesh().elements;
  const size_t k = elements.empty() ? 3 : elements.front().corners.size();
  for (const Element& e : elements)
    if (e.corners.size() != k)
      throw py::value_error("radview: " + s.viewed->file.path +
                            ": its elements have different numbers of corners; use element_corners and "
                            "element_offsets");
  py::array_t<uint32_t> out({py::ssize_t(elements.size()), py::ssize_t(k)});
  uint32_t* o = out.mutable_data();
  for (const Element& e : elements) o = std::copy(e.corners.begin(), e.corners.end(), o);
  return out;
}

template <typename Field>
py::array_t<int32_t> perElement(const Solution& s, Field field) {
  const std::vector<Element>& elements = s.mesh().elements;
  py::array_t<int32_t> out(static_cast<py::ssize_t>(elements.size()));
  int32_t* o = out.mutable_data();
  for (const Element& e : elements) *o++ = int32_t(field(e));
  return out;
}

// The discontinuity edges as a structured array (a, b: end nodes; order: -1, 0 or 1 for C-1, C0,
// C1), a view of the mesh's own records.
py::array discontinuityEdges(const py::object& self) {
  static_assert(sizeof(Continuity) == 1 && offsetof(DiscontinuityEdge, order) == 8);
  const std::vector<DiscontinuityEdge>& edges = self.cast<const Solution&>().mesh().discontinuities;
  py::dict fields;
  fields["names"] = py::make_tuple("a", "b", "order");
  fields["formats"] = py::make_tuple("<u4", "<u4", "i1");
  fields["offsets"] = py::make_tuple(offsetof(DiscontinuityEdge, a), offsetof(DiscontinuityEdge, b),
                                     offsetof(DiscontinuityEdge, order));
  fields["itemsize"] = sizeof(DiscontinuityEdge);
  const py::dtype dtype = py::dtype::from_args(fields);
  return readOnlyView(dtype, {py::ssize_t(edges.size())}, {py::ssize_t(sizeof(DiscontinuityEdge))}, edges.data(), self);
}

}  // namespace

std::string pathArgument(const py::handle& path, const std::string& function) {
  if (py::hasattr(path, "closed") && py::hasattr(path, "name")) {  // a file object
    const std::string name = py::str(path.attr("name"));
    if (path.attr("closed").cast<bool>()) throw py::value_error(function + ": the file " + name + " is closed");
    return name;
  }
  try {
    return py::str(py::module_::import("os").attr("fspath")(path));
  } catch (const py::error_already_set&) {
    throw py::type_error(function + ": expected a path (str or os.PathLike) or an open file, not " +
                         std::string(py::str(path.get_type().attr("__name__"))));
  }
}

Solution load(const py::handle& path, const py::kwargs& options) {
  const std::string file = pathArgument(path, "radview.load");
  CLI::App command;
  ImportOptions import;
  SceneLightOptions light;
  double elementSize = 0.0;
  addImportOptions(command, import);
  addSceneLightOptions(command, light);
  command.add_option("--element-size", elementSize)->check(CLI::Range(1e-12, 1e12));
  parseKeywordOptions(command, options, "radview.load");
  py::gil_scoped_release release;
  Solution solution;
  solution.viewed = std::make_shared<const ViewedFile>(
      openForViewing(file, elementSize, import, light, nullptr, solveProgressOnTerminal(light)));
  return solution;
}

py::class_<Solution> bindSolution(py::module_& m) {
  py::class_<Solution> solution(m, "Solution",
                                R"(A radiosity solution as radview shows it: a solution file, another tool's
mesh with vertex colours, or a scene solved when it was opened. Made by radview.load.

Its arrays are read-only numpy views of radview's own storage (no copies), kept alive with it:
positions, B, gradients and standard_errors, one row per node, and discontinuity_edges.
The element arrays are copies, since elements hold corner lists of any length.)");
  solution
      .def_property_readonly(
          "path", [](const Solution& s) { return s.viewed->file.path; }, "The file it was opened from.")
      .def_property_readonly(
          "is_solution", [](const Solution& s) { return s.viewed->file.isSolution; },
          "True for a solution or another tool's mesh; False for a scene, solved (or lit) when opened.")
      .def_property_readonly(
          "lighting", [](const Solution& s) { return s.viewed->lighting; },
          "For a scene: how it was lit, in words (the solve's summary, or the direct-only preview).")
      .def_property_readonly(
          "warnings", [](const Solution& s) { return s.viewed->file.warnings; }, "What the reader warned of.")
      .def_property_readonly(
          "node_count", [](const Solution& s) { return s.mesh().nodes.size(); }, "Nodes.")
      .def_property_readonly(
          "element_count", [](const Solution& s) { return s.mesh().elements.size(); }, "Elements.")
      .def_property_readonly(
          "positions", [](const py::object& self) { return nodeField(self, offsetof(Node, position), false); },
          "(nodes, 3) float64: each node's world position. A view, read-only.")
      .def_property_readonly(
          "B", [](const py::object& self) { return nodeField(self, offsetof(Node, B), false); },
          "(nodes, 3) float64: each node's radiosity B, RGB. A view, read-only.")
      .def_property_readonly(
          "gradients",
          [](const py::object& self) -> py::object {
            if (!self.cast<const Solution&>().mesh().hasGradients) return py::none();
            return nodeField(self, offsetof(Node, gradient), true);
          },
          "(nodes, 3, 3) float64: [node, channel] is the surface gradient of that channel of B, world space; "
          "None when the file stores none. A view, read-only.")
      .def_property_readonly(
          "standard_errors",
          [](const py::object& self) -> py::object {
            if (!self.cast<const Solution&>().mesh().hasStandardErrors) return py::none();
            return nodeField(self, offsetof(Node, standardError), false);
          },
          "(nodes, 3) float64: the solver's standard error of each node's B; None when it estimated none. "
          "A view, read-only.")
      .def_property_readonly("elements", &uniformElements,
                             "(elements, k) uint32: corner node indices, counter-clockwise, when every element has "
                             "k corners (raises ValueError otherwise: see element_corners). A copy.")
      .def_property_readonly(
          "element_corners", [](const Solution& s) { return py::object(elementCornerLists(s)[0]); },
          "uint32: every element's corners, one after another (element i's are "
          "element_corners[element_offsets[i]:element_offsets[i + 1]]). A copy.")
      .def_property_readonly(
          "element_offsets", [](const Solution& s) { return py::object(elementCornerLists(s)[1]); },
          "(elements + 1,) int64: where each element's corners start in element_corners. A copy.")
      .def_property_readonly(
          "element_surfaces",
          [](const Solution& s) { return perElement(s, [](const Element& e) { return e.surface; }); },
          "(elements,) int32: the scene polygon each element meshes, -1 where unknown. A copy.")
      .def_property_readonly(
          "element_materials",
          [](const Solution& s) { return perElement(s, [](const Element& e) { return e.material; }); },
          "(elements,) int32: each element's material index. A copy.")
      .def_property_readonly("discontinuity_edges", &discontinuityEdges,
                             "Structured array of the edges across which B is not C1: a, b (end nodes), order "
                             "(-1: value jumps, 0: derivative jumps, 1: smooth). A view, read-only.")
      .def("__repr__", [](const Solution& s) {
        return "<radview.Solution " + s.viewed->file.path + ": " + std::to_string(s.mesh().elements.size()) +
               " elements, " + std::to_string(s.mesh().nodes.size()) + " nodes>";
      });
  m.def("load", &load, py::arg("path"), R"(load(path, **options) -> Solution

Opens a solution, another tool's mesh (.ply, .obj, ... with vertex colours) or a glTF scene, as
`radview render` does. A scene is solved first, with radview solve's defaults unless told
otherwise. Options are the command line's, as keywords: element_size=0.05, direct_only=True,
samples=64, discontinuity_meshing=False, ... Raises radview.Error with the command line's
message for a file or option radview refuses.)");
  return solution;
}

}  // namespace radview::python
