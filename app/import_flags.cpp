#include "app/import_flags.h"

#include "core/strings.h"

#include <algorithm>
#include <map>
#include <optional>
#include <string_view>
#include <vector>

namespace radview {

void addImportOptions(CLI::App& command, ImportOptions& import) {
  const std::map<std::string, ColourEncoding> encodings = {
      {"auto", ColourEncoding::Auto}, {"linear", ColourEncoding::Linear}, {"srgb", ColourEncoding::Srgb}};
  command
      .add_option("--colours", import.colours,
                  "Vertex colours: auto (floats linear, 8/16-bit sRGB-decoded, glTF COLOR_0 linear), "
                  "linear (all linear) or srgb (all display colours, sRGB-decoded)")
      ->transform(CLI::CheckedTransformer(encodings))
      ->default_str("auto");
  const std::map<std::string, ReadAs> readings = {
      {"auto", ReadAs::Auto}, {"scene", ReadAs::Scene}, {"solution", ReadAs::Solution}};
  command
      .add_option("--read-as", import.readAs,
                  "glTF with COLOR_0: auto (a radiosity mesh unless a material emits), scene, or solution "
                  "(B from COLOR_0)")
      ->transform(CLI::CheckedTransformer(readings))
      ->default_str("auto");
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
