#include "app/import_flags.h"

#include "core/strings.h"

#include <algorithm>
#include <optional>
#include <string_view>
#include <vector>

namespace radview {

namespace {

// `text` as one of `choices`, or a CLI error listing them.
template <class T>
T choice(const std::string& option, const std::string& text, const std::vector<std::pair<std::string, T>>& choices) {
  std::string names;
  for (const auto& [name, value] : choices) {
    if (name == text) return value;
    names += (names.empty() ? "" : ", ") + name;
  }
  throw CLI::ValidationError(option, "'" + text + "': expected one of " + names);
}

}  // namespace

void addImportOptions(CLI::App& command, ImportOptions& import) {
  command.add_option_function<std::string>(
      "--colours",
      [&import](const std::string& text) {
        import.colours = choice<ColourEncoding>("--colours", text,
                                                {{"auto", ColourEncoding::Auto},
                                                 {"linear", ColourEncoding::Linear},
                                                 { "srgb",
                                                   ColourEncoding::Srgb }});
      },
      "Vertex colours: auto (floats linear, 8/16-bit sRGB-decoded, glTF COLOR_0 linear; the default), "
      "linear (all linear) or srgb (all display colours, sRGB-decoded)");
  command.add_option_function<std::string>(
      "--read-as",
      [&import](const std::string& text) {
        import.readAs = choice<ReadAs>("--read-as", text, {{"auto", ReadAs::Auto}, {"scene", ReadAs::Scene}, {
                                                             "solution",
                                                             ReadAs::Solution
                                                           }});
      },
      "glTF with COLOR_0: auto (a radiosity mesh unless a material emits; the default), scene, or solution "
      "(B from COLOR_0)");
  command.add_option_function<std::string>(
      "--rho",
      [&import](const std::string& text) {
        std::vector<double> values;
        for (size_t start = 0; start <= text.size();) {
          const size_t end = std::min(text.find(',', start), text.size());
          const std::optional<double> v = parseFiniteNumber(std::string_view(text).substr(start, end - start));
          if (!v || *v < 0.0 || *v > 1.0)
            throw CLI::ValidationError("--rho", "'" + text + "': expected R,G,B or one value, each in [0, 1]");
          values.push_back(*v);
          start = end + 1;
        }
        if (values.size() != 1 && values.size() != 3)
          throw CLI::ValidationError("--rho", "'" + text + "': expected R,G,B or one value, each in [0, 1]");
        import.rho = values.size() == 1 ? Rgb(values[0]) : Rgb(values[0], values[1], values[2]);
      },
      "Meshes without reflectances (PLY, OBJ): rho of every element, R,G,B or one grey value, for the final gather");
  command.add_option_function<double>(
      "--emitters-above", [&import](double luminance) { import.emittersAbove = luminance; },
      "Meshes without emitters: elements whose every node's luminance reaches this emit their mean B, for the "
      "final gather");
  command.add_option("--value-property", import.valueProperty,
                     "PLY: the per-vertex scalar property read as grey B (default: red green blue, then "
                     "radiosity or B)");
}

}  // namespace radview
