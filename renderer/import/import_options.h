#pragma once
// How a mesh from another tool is read (PLY, OBJ, glTF COLOR_0): what its colours mean and
// which reading of a glTF file is wanted. import/README.md states the rules.
#include "core/types.h"

#include <optional>
#include <string>

namespace radview {

// What the numbers of a vertex colour are. Auto: floats are linear radiosity as they are
// (any range), 8- and 16-bit integers are display colours, sRGB-decoded to linear; glTF
// COLOR_0 is linear, as its specification says. Linear: every value is linear (integers
// only scaled to [0, 1]). Srgb: every value is a display colour, floats included.
enum class ColourEncoding { Auto, Linear, Srgb };

// A glTF file with COLOR_0: Auto reads it as a radiosity mesh when no material emits, as a
// scene (COLOR_0 then multiplies rho) otherwise.
enum class ReadAs { Auto, Scene, Solution };

struct ImportOptions {
  ColourEncoding colours = ColourEncoding::Auto;
  ReadAs readAs = ReadAs::Auto;
  std::string valueProperty;  // PLY: a per-vertex scalar property read as grey B

  // What the final gather needs and a mesh of colours does not say, assumed on request: a
  // reflectance for every element, and which elements emit (those whose every node's
  // luminance reaches the threshold; they emit their mean nodal B).
  std::optional<Rgb> rho;
  std::optional<double> emittersAbove;
};

}  // namespace radview
