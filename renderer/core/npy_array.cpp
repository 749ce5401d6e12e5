#include "core/npy_array.h"

#include "core/error.h"
#include "core/input_file.h"

#include <cstdint>
#include <cstring>
#include <optional>

// The data are copied as they lie: .npy's '<f8' and '<f4' are the host's own doubles and floats.
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "npy_array.cpp reads and writes little-endian data as is");

namespace radview {

namespace {

constexpr char kMagic[] = "\x93NUMPY";
constexpr size_t kMagicBytes = 6;

// The header is a Python dict literal: {'descr': '<f8', 'fortran_order': False, 'shape': (2, 3), }
// (numpy.lib.format). This reads exactly that grammar: string keys; a string, True/False or a
// tuple of non-negative integers as values; commas, a trailing one allowed; blanks anywhere.
class HeaderReader {
 public:
  HeaderReader(const std::string& text, const std::string& source) : text_(text), source_(source) {}

  std::string descr;
  std::optional<bool> fortranOrder;
  std::optional<std::vector<uint64_t>> shape;

  void read() {
    expect('{');
    while (!peek('}')) {
      const std::string key = quoted();
      expect(':');
      if (key == "descr") {
        descr = quoted();
      } else if (key == "fortran_order") {
        fortranOrder = boolean();
      } else if (key == "shape") {
        shape = tuple();
      } else {
        fail("unknown key '" + key + "'");
      }
      if (!peek('}')) expect(',');
    }
    expect('}');
    blanks();
    if (at_ != text_.size()) fail("text after the header's closing brace");
    if (descr.empty() || !fortranOrder || !shape) fail("the header lacks descr, fortran_order or shape");
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw Error(source_, "not a .npy array: " + what); }
  void blanks() {
    while (at_ < text_.size() && (text_[at_] == ' ' || text_[at_] == '\n' || text_[at_] == '\t')) ++at_;
  }
  bool peek(char c) {
    blanks();
    return at_ < text_.size() && text_[at_] == c;
  }
  void expect(char c) {
    if (!peek(c)) fail(std::string("expected '") + c + "' in the header");
    ++at_;
  }
  std::string quoted() {
    blanks();
    if (at_ >= text_.size() || (text_[at_] != '\'' && text_[at_] != '"')) fail("expected a quoted key or string");
    const char quote = text_[at_++];
    const size_t end = text_.find(quote, at_);
    if (end == std::string::npos) fail("an unterminated string in the header");
    std::string out = text_.substr(at_, end - at_);
    at_ = end + 1;
    return out;
  }
  bool boolean() {
    blanks();
    for (const auto& [word, value] : {std::pair<const char*, bool>{"True", true}, {"False", false}})
      if (text_.compare(at_, std::strlen(word), word) == 0) {
        at_ += std::strlen(word);
        return value;
      }
    fail("fortran_order must be True or False");
  }
  std::vector<uint64_t> tuple() {
    expect('(');
    std::vector<uint64_t> out;
    while (!peek(')')) {
      blanks();
      uint64_t value = 0;
      size_t digits = 0;
      for (; at_ < text_.size() && text_[at_] >= '0' && text_[at_] <= '9'; ++at_, ++digits) {
        if (value > (UINT64_MAX - 9) / 10) fail("a dimension too large");
        value = value * 10 + uint64_t(text_[at_] - '0');
      }
      if (digits == 0) fail("the shape holds something other than whole numbers");
      if (out.size() == 8) fail("more than 8 dimensions");
      out.push_back(value);
      if (!peek(')')) expect(',');
    }
    expect(')');
    return out;
  }

  const std::string& text_;
  const std::string& source_;
  size_t at_ = 0;
};

uint32_t littleEndian(const unsigned char* p, size_t bytes) {
  uint32_t v = 0;
  for (size_t i = bytes; i-- > 0;) v = v << 8 | p[i];
  return v;
}

}  // namespace

std::string npyHeader(size_t rows, size_t columns) {
  std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': (" + std::to_string(rows) + ", " +
                       std::to_string(columns) + "), }";
  const size_t fixed = kMagicBytes + 2 + 2;  // magic, version, header length
  header.append((64 - (fixed + header.size() + 1) % 64) % 64, ' ');
  header += '\n';
  std::string out(kMagic, kMagicBytes);
  out += '\x01';
  out += '\x00';
  out += char(header.size() & 0xff);
  out += char(header.size() >> 8);
  return out + header;
}

std::string npyBytes(const NpyMatrix& matrix) {
  std::string out = npyHeader(matrix.rows, matrix.columns);
  const size_t dataAt = out.size();
  out.resize(dataAt + matrix.values.size() * sizeof(double));
  std::memcpy(&out[dataAt], matrix.values.data(), matrix.values.size() * sizeof(double));
  return out;
}

NpyMatrix parseNpy(const char* data, size_t size, const std::string& source) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(data);
  if (size < kMagicBytes + 4 || std::memcmp(data, kMagic, kMagicBytes) != 0)
    throw Error(source, "not a .npy array: it does not start with \\x93NUMPY");
  const unsigned major = bytes[6];
  if (major < 1 || major > 3)
    throw Error(source, "not a .npy array radview reads: format version " + std::to_string(major) + " (1 to 3 are)");
  const size_t lengthBytes = major == 1 ? 2 : 4;
  if (size < kMagicBytes + 2 + lengthBytes) throw Error(source, "not a .npy array: cut off in its header");
  const uint64_t headerBytes = littleEndian(bytes + 8, lengthBytes);
  const uint64_t dataAt = kMagicBytes + 2 + lengthBytes + headerBytes;
  if (dataAt > size) throw Error(source, "not a .npy array: its header runs past the end of the file");
  const std::string text(data + kMagicBytes + 2 + lengthBytes, size_t(headerBytes));
  HeaderReader header(text, source);
  header.read();

  size_t itemBytes = 0;
  if (header.descr == "<f8") {
    itemBytes = 8;
  } else if (header.descr == "<f4") {
    itemBytes = 4;
  } else {
    throw Error(source, "holds '" + header.descr + "' numbers; radview reads float64 or float32, little-endian ('<f8', '<f4')");
  }
  if (*header.fortranOrder) throw Error(source, "is in Fortran order; save it in C order (numpy's default)");
  const std::vector<uint64_t>& shape = *header.shape;
  if (shape.empty() || shape.size() > 2)
    throw Error(source, "has " + std::to_string(shape.size()) + " dimensions; radview reads a table (1 or 2)");
  NpyMatrix matrix;
  matrix.itemBytes = itemBytes;
  matrix.rows = shape.size() == 2 ? shape[0] : 1;
  matrix.columns = shape.back();
  const uint64_t available = (size - dataAt) / itemBytes;
  if (matrix.columns != 0 && matrix.rows > available / matrix.columns)
    throw Error(source, "is cut off: its shape asks for more numbers than the file holds");
  const uint64_t count = uint64_t(matrix.rows) * matrix.columns;
  if (count * itemBytes != size - dataAt)
    throw Error(source, "holds " + std::to_string(size - dataAt) + " bytes of data where its shape asks for " +
                            std::to_string(count * itemBytes));
  matrix.values.resize(count);
  const char* in = data + dataAt;
  if (itemBytes == 8) {
    std::memcpy(matrix.values.data(), in, count * 8);
  } else {
    for (uint64_t i = 0; i < count; ++i) {
      float v;
      std::memcpy(&v, in + 4 * i, 4);
      matrix.values[i] = v;
    }
  }
  return matrix;
}

NpyMatrix readNpy(const std::string& path) {
  const std::vector<char> bytes = readInputFile(path, "a .npy array");
  return parseNpy(bytes.data(), bytes.size(), path);
}

}  // namespace radview
