#pragma once
// A PLY file (Greg Turk's polygon file format) read whole: its header's elements and
// properties with their declared types, and every value, for ASCII and binary files of either
// byte order. radview reads PLY itself rather than through Assimp because a radiosity mesh needs
// what Assimp's PLY importer does not pass on: the declared type of each colour (8-bit colours
// are display values, floats are radiosity), per-vertex scalar properties, and elements other
// than vertices and faces (the `edge` element that carries discontinuity tags).
#include <cstdint>
#include <string>
#include <vector>

namespace radview {

enum class PlyType : uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };
const char* toString(PlyType type);  // the spec's names: "char", "uchar", ... "double"
bool isInteger(PlyType type);
bool isSigned(PlyType type);
// The largest value of an unsigned integer type (255 for uchar); 1 for the float types.
double integerMax(PlyType type);

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  // of the values (of a list's items)
  bool isList = false;
  PlyType countType = PlyType::UInt8;  // lists only: the type of the item count

  // Scalars: one value per element. Lists: the items of every element, flattened, with
  // element i's items at [offsets[i], offsets[i + 1]).
  std::vector<double> values;
  std::vector<uint64_t> offsets;
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  std::vector<PlyProperty> properties;

  // The property called `name`, or nullptr.
  const PlyProperty* find(const std::string& name) const;
};

struct PlyFile {
  enum class Format { Ascii, BinaryLittleEndian, BinaryBigEndian };
  Format format = Format::Ascii;
  std::vector<PlyElement> elements;

  // The element called `name`, or nullptr.
  const PlyElement* find(const std::string& name) const;
};

// Reads `bytes`, the contents of the file `path` (named in errors). Header lines may end in LF,
// CR LF or a bare CR; ASCII bodies hold one element per line. Throws Error(path, ...) naming the
// first fault: no "ply" magic, an unknown format, type or keyword, a count that the file's
// bytes cannot hold, a truncated binary body or trailing bytes, an ASCII line with too few or
// too many values or a value that is not a number of its type.
PlyFile parsePly(const std::vector<char>& bytes, const std::string& path);

// The file at `path`, through core/input_file.h's checks. Throws Error(path, ...).
PlyFile readPly(const std::string& path);

}  // namespace radview
