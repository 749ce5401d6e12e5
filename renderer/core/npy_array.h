#pragma once
// Two-dimensional arrays of numbers in NumPy's .npy format (format version 1.0, 2.0 or 3.0),
// so that scripts hand radview points and take its samples back without text: numpy.load and
// numpy.save on the other side. radview writes little-endian float64 ('<f8'), C order; it
// reads little-endian float32 or float64, C order, one or two dimensions (one dimension: a
// single row), and refuses anything else naming the file and what is wrong.
#include <cstddef>
#include <string>
#include <vector>

namespace radview {

struct NpyMatrix {
  size_t rows = 0, columns = 0;
  std::vector<double> values;  // row-major, rows * columns
  size_t itemBytes = 8;        // as stored: 4 (float32) or 8 (float64)
  double at(size_t row, size_t column) const { return values[row * columns + column]; }
};

// The start of a .npy file of rows x columns float64 ('<f8', C order, format 1.0), its header
// padded so the data start on a 64-byte boundary, as numpy writes them; the data follow,
// row-major, as the host's doubles.
std::string npyHeader(size_t rows, size_t columns);

// The whole .npy file for `matrix`.
std::string npyBytes(const NpyMatrix& matrix);

// Parses a whole .npy file. Throws Error(source, what is wrong).
NpyMatrix parseNpy(const char* data, size_t size, const std::string& source);

// readInputFile (core/input_file.h), then parseNpy. Throws Error(path, ...).
NpyMatrix readNpy(const std::string& path);

}  // namespace radview
