// PLY reading (import/ply_file.h). Nothing in the header is trusted: the counts it declares
// are checked against the bytes the body has before anything is allocated for them, and
// every list count against the bytes that remain.
#include "import/ply_file.h"

#include "core/error.h"
#include "core/input_file.h"
#include "core/limits.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <string_view>

namespace radview {

namespace {

struct TypeInfo {
  PlyType type;
  const char* name;
  const char* alias;
  int bytes;
};

constexpr TypeInfo kTypes[] = {
    {PlyType::Int8, "char", "int8", 1},        {PlyType::UInt8, "uchar", "uint8", 1},
    {PlyType::Int16, "short", "int16", 2},     {PlyType::UInt16, "ushort", "uint16", 2},
    {PlyType::Int32, "int", "int32", 4},       {PlyType::UInt32, "uint", "uint32", 4},
    {PlyType::Float32, "float", "float32", 4}, {PlyType::Float64, "double", "float64", 8},
};

const TypeInfo& info(PlyType type) { return kTypes[int(type)]; }

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && isSpace(line[i])) ++i;
    const size_t start = i;
    while (i < line.size() && !isSpace(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

// Lines of `bytes` from `pos`, ending in LF, CR LF or a bare CR.
class LineReader {
 public:
  LineReader(const std::vector<char>& bytes, size_t pos) : bytes_(bytes), pos_(pos) {}

  bool next(std::string_view& line) {
    if (pos_ >= bytes_.size()) return false;
    const size_t start = pos_;
    while (pos_ < bytes_.size() && bytes_[pos_] != '\n' && bytes_[pos_] != '\r') ++pos_;
    line = std::string_view(bytes_.data() + start, pos_ - start);
    if (pos_ < bytes_.size() && bytes_[pos_] == '\r') {
      ++pos_;
      if (pos_ < bytes_.size() && bytes_[pos_] == '\n') ++pos_;
    } else if (pos_ < bytes_.size()) {
      ++pos_;  // the LF
    }
    ++number_;
    return true;
  }
  size_t position() const { return pos_; }
  uint64_t lineNumber() const { return number_; }

 private:
  const std::vector<char>& bytes_;
  size_t pos_;
  uint64_t number_ = 0;
};

class PlyParser {
 public:
  PlyParser(const std::vector<char>& bytes, const std::string& path) : bytes_(bytes), path_(path) {}

  PlyFile parse() {
    const size_t bodyStart = parseHeader();
    checkCountsFit(bytes_.size() - bodyStart);
    for (PlyElement& e : file_.elements)
      for (PlyProperty& p : e.properties) {
        if (p.isList) {
          p.offsets.reserve(e.count + 1);
          p.offsets.push_back(0);
        } else {
          p.values.reserve(e.count);
        }
      }
    if (file_.format == PlyFile::Format::Ascii)
      readAscii(bodyStart);
    else
      readBinary(bodyStart);
    return std::move(file_);
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw Error(path_, problem); }
  [[noreturn]] void failAt(uint64_t line, const std::string& problem) const {
    fail("line " + std::to_string(line) + ": " + problem);
  }

  PlyType typeNamed(std::string_view name, uint64_t line) const {
    for (const TypeInfo& t : kTypes)
      if (name == t.name || name == t.alias) return t.type;
    failAt(line, "unknown property type \"" + std::string(name) + "\"");
  }

  // Returns the offset of the body's first byte.
  size_t parseHeader() {
    LineReader lines(bytes_, 0);
    std::string_view line;
    if (!lines.next(line) || tokens(line).size() != 1 || tokens(line)[0] != "ply")
      fail("not a PLY file (the first line is not \"ply\")");
    bool sawFormat = false;
    while (true) {
      const size_t lineStart = lines.position();
      if (!lines.next(line)) fail("the header has no end_header line");
      const std::vector<std::string_view> t = tokens(line);
      const uint64_t number = lines.lineNumber();
      if (t.empty()) continue;
      const std::string_view keyword = t[0];
      if (keyword == "comment" || keyword == "obj_info") continue;
      if (keyword == "end_header") {
        if (!sawFormat) failAt(number, "end_header before a format line");
        if (t.size() != 1) failAt(number, "end_header is followed by other text");
        return bodyStart(lineStart, line.size());
      }
      if (keyword == "format") {
        if (sawFormat) failAt(number, "a second format line");
        if (t.size() != 3)
          failAt(number, "a format line is \"format <ascii|binary_little_endian|binary_big_endian> 1.0\"");
        if (t[1] == "ascii")
          file_.format = PlyFile::Format::Ascii;
        else if (t[1] == "binary_little_endian")
          file_.format = PlyFile::Format::BinaryLittleEndian;
        else if (t[1] == "binary_big_endian")
          file_.format = PlyFile::Format::BinaryBigEndian;
        else
          failAt(number, "unknown format \"" + std::string(t[1]) + "\"");
        if (t[2] != "1.0") failAt(number, "PLY version " + std::string(t[2]) + " (radview reads 1.0)");
        sawFormat = true;
      } else if (keyword == "element") {
        if (t.size() != 3) failAt(number, "an element line is \"element <name> <count>\"");
        PlyElement element;
        element.name = std::string(t[1]);
        const auto [end, ec] = std::from_chars(t[2].data(), t[2].data() + t[2].size(), element.count);
        if (ec != std::errc() || end != t[2].data() + t[2].size())
          failAt(number, "element " + element.name + ": count \"" + std::string(t[2]) + "\" is not a whole number");
        if (file_.find(element.name)) failAt(number, "a second element named " + element.name);
        checkLimit(path_, element.count, kMaxPlyEntries, element.name + " entries");
        file_.elements.push_back(std::move(element));
      } else if (keyword == "property") {
        if (file_.elements.empty()) failAt(number, "a property before any element");
        PlyProperty property;
        if (t.size() == 5 && t[1] == "list") {
          property.isList = true;
          property.countType = typeNamed(t[2], number);
          property.type = typeNamed(t[3], number);
          if (!isInteger(property.countType))
            failAt(number,
                   "list " + std::string(t[4]) + ": its count type " + std::string(t[2]) + " is not an integer type");
          property.name = std::string(t[4]);
        } else if (t.size() == 3 && t[1] != "list") {
          property.type = typeNamed(t[1], number);
          property.name = std::string(t[2]);
        } else {
          failAt(number,
                 "a property line is \"property <type> <name>\" or \"property list <count type> <type> <name>\"");
        }
        PlyElement& element = file_.elements.back();
        if (element.find(property.name))
          failAt(number, "element " + element.name + " has two properties named " + property.name);
        element.properties.push_back(std::move(property));
      } else {
        failAt(number, "unknown header keyword \"" + std::string(keyword) + "\"");
      }
    }
  }

  // The body starts after end_header's terminator. In a binary file that terminator is taken
  // as written: a bare CR is one byte even when the body's first byte is an LF.
  size_t bodyStart(size_t lineStart, size_t lineLength) const {
    size_t pos = lineStart + lineLength;
    if (pos < bytes_.size() && bytes_[pos] == '\r') {
      ++pos;
      if (pos < bytes_.size() && bytes_[pos] == '\n' && !bareCrHeader()) ++pos;
    } else if (pos < bytes_.size() && bytes_[pos] == '\n') {
      ++pos;
    }
    return pos;
  }

  // Whether the first line ("ply") ends in a CR not followed by LF.
  bool bareCrHeader() const {
    size_t i = 0;
    while (i < bytes_.size() && bytes_[i] != '\r' && bytes_[i] != '\n') ++i;
    return i + 1 < bytes_.size() && bytes_[i] == '\r' && bytes_[i + 1] != '\n';
  }

  // Each element needs at least this many bytes in the body: binary, its scalars and list
  // counts; ASCII, a digit and a separator per value.
  uint64_t minimumBytes(const PlyElement& element) const {
    uint64_t bytes = 0;
    for (const PlyProperty& p : element.properties)
      bytes += file_.format == PlyFile::Format::Ascii ? 2 : uint64_t(info(p.isList ? p.countType : p.type).bytes);
    return bytes;
  }

  void checkCountsFit(uint64_t bodyBytes) const {
    uint64_t needed = 0;
    for (const PlyElement& e : file_.elements) {
      const uint64_t each = minimumBytes(e);
      if (each == 0) {
        if (e.count > 0) fail("element " + e.name + " has " + std::to_string(e.count) + " entries but no properties");
        continue;
      }
      // Written to stay clear of overflow: count * each > bodyBytes - needed.
      if (e.count > (bodyBytes - needed) / each + 1 || e.count * each > bodyBytes - needed)
        fail("the header declares " + std::to_string(e.count) + " " + e.name + " entries, more than the " +
             std::to_string(bodyBytes) + " bytes after the header can hold (a truncated file or a wrong count)");
      needed += e.count * each;
    }
  }

  // --- binary -------------------------------------------------------------------------------

  double readBinaryValue(PlyType type, const char*& at, const char* end, const PlyElement& e, uint64_t i) const {
    const int size = info(type).bytes;
    if (end - at < size)
      fail("the body ends inside " + e.name + " " + std::to_string(i) +
           " (the file is truncated, or a count is wrong)");
    unsigned char raw[8];
    std::memcpy(raw, at, size_t(size));
    at += size;
    if (file_.format == PlyFile::Format::BinaryBigEndian)
      for (int k = 0; k < size / 2; ++k) std::swap(raw[k], raw[size - 1 - k]);
    switch (type) {
      case PlyType::Int8:
        return double(int8_t(raw[0]));
      case PlyType::UInt8:
        return double(raw[0]);
      case PlyType::Int16: {
        int16_t v;
        std::memcpy(&v, raw, 2);
        return double(v);
      }
      case PlyType::UInt16: {
        uint16_t v;
        std::memcpy(&v, raw, 2);
        return double(v);
      }
      case PlyType::Int32: {
        int32_t v;
        std::memcpy(&v, raw, 4);
        return double(v);
      }
      case PlyType::UInt32: {
        uint32_t v;
        std::memcpy(&v, raw, 4);
        return double(v);
      }
      case PlyType::Float32: {
        float v;
        std::memcpy(&v, raw, 4);
        return double(v);
      }
      case PlyType::Float64: {
        double v;
        std::memcpy(&v, raw, 8);
        return v;
      }
    }
    return 0.0;
  }

  void readBinary(size_t start) {
    const char* at = bytes_.data() + start;
    const char* end = bytes_.data() + bytes_.size();
    for (PlyElement& e : file_.elements)
      for (uint64_t i = 0; i < e.count; ++i)
        for (PlyProperty& p : e.properties) {
          if (!p.isList) {
            p.values.push_back(readBinaryValue(p.type, at, end, e, i));
            continue;
          }
          const double count = readBinaryValue(p.countType, at, end, e, i);
          checkListCount(count, e, i, p);
          if (uint64_t(count) * uint64_t(info(p.type).bytes) > uint64_t(end - at))
            fail(e.name + " " + std::to_string(i) + ": its " + p.name + " list of " + std::to_string(uint64_t(count)) +
                 " items runs past the end of the file");
          for (uint64_t k = 0; k < uint64_t(count); ++k) p.values.push_back(readBinaryValue(p.type, at, end, e, i));
          p.offsets.push_back(p.values.size());
        }
    for (const char* c = at; c < end; ++c)
      if (!std::isspace(static_cast<unsigned char>(*c)))
        fail(std::to_string(end - at) + " bytes follow the last element the header declares (a count is wrong)");
  }

  void checkListCount(double count, const PlyElement& e, uint64_t i, const PlyProperty& p) const {
    if (count < 0) fail(e.name + " " + std::to_string(i) + ": its " + p.name + " list has a negative count");
    checkLimit(path_, p.values.size() + uint64_t(count), kMaxPlyListItems, "items in the " + p.name + " lists");
  }

  // --- ASCII --------------------------------------------------------------------------------

  double parseAscii(std::string_view token, PlyType type, uint64_t line, const PlyElement& e, uint64_t i,
                    const PlyProperty& p) const {
    const char* first = token.data();
    const char* last = token.data() + token.size();
    if (first < last && *first == '+') ++first;
    double value = 0.0;
    const auto [end, ec] = std::from_chars(first, last, value);
    const bool integral = std::isfinite(value) && value == std::floor(value);
    if (ec != std::errc() || end != last || (isInteger(type) && !integral))
      failAt(line, e.name + " " + std::to_string(i) + ": " + p.name + " \"" + std::string(token) + "\" is not " +
                       (isInteger(type) ? "an integer" : "a number"));
    if (isInteger(type)) {
      const double low = isSigned(type) ? -integerMax(type) - 1.0 : 0.0;
      if (value < low || value > integerMax(type))
        failAt(line, e.name + " " + std::to_string(i) + ": " + p.name + " " + std::string(token) + " does not fit in " +
                         toString(type));
    }
    return value;
  }

  void readAscii(size_t start) {
    LineReader lines(bytes_, start);
    uint64_t lineOffset = 0;  // the header's lines, so that errors give the line in the file
    {
      LineReader header(bytes_, 0);
      std::string_view line;
      while (header.position() < start && header.next(line)) ++lineOffset;
    }
    std::string_view line;
    for (PlyElement& e : file_.elements)
      for (uint64_t i = 0; i < e.count; ++i) {
        std::vector<std::string_view> t;
        do {
          if (!lines.next(line))
            fail("the file ends before " + e.name + " " + std::to_string(i) + " (of " + std::to_string(e.count) +
                 " the header declares)");
          t = tokens(line);
        } while (t.empty());
        const uint64_t number = lineOffset + lines.lineNumber();
        size_t k = 0;
        for (PlyProperty& p : e.properties) {
          auto take = [&](PlyType type) {
            if (k >= t.size())
              failAt(number, e.name + " " + std::to_string(i) + " has " + std::to_string(t.size()) +
                                 " values, too few for the header's properties");
            return parseAscii(t[k++], type, number, e, i, p);
          };
          if (!p.isList) {
            p.values.push_back(take(p.type));
            continue;
          }
          const double count = take(p.countType);
          checkListCount(count, e, i, p);
          if (count > double(t.size() - k))
            failAt(number, e.name + " " + std::to_string(i) + ": its " + p.name + " list of " +
                               std::to_string(uint64_t(count)) + " items is longer than the line");
          for (uint64_t n = 0; n < uint64_t(count); ++n) p.values.push_back(take(p.type));
          p.offsets.push_back(p.values.size());
        }
        if (k != t.size())
          failAt(number, e.name + " " + std::to_string(i) + " has " + std::to_string(t.size()) +
                             " values where the header's properties take " + std::to_string(k));
      }
    while (lines.next(line))
      if (!tokens(line).empty())
        failAt(lineOffset + lines.lineNumber(), "text after the last element the header declares (a count is wrong)");
  }

  const std::vector<char>& bytes_;
  const std::string& path_;
  PlyFile file_;
};

}  // namespace

const char* toString(PlyType type) { return info(type).name; }

bool isInteger(PlyType type) { return type != PlyType::Float32 && type != PlyType::Float64; }

bool isSigned(PlyType type) {
  return type == PlyType::Int8 || type == PlyType::Int16 || type == PlyType::Int32 || !isInteger(type);
}

double integerMax(PlyType type) {
  switch (type) {
    case PlyType::Int8:
      return 127.0;
    case PlyType::UInt8:
      return 255.0;
    case PlyType::Int16:
      return 32767.0;
    case PlyType::UInt16:
      return 65535.0;
    case PlyType::Int32:
      return 2147483647.0;
    case PlyType::UInt32:
      return 4294967295.0;
    default:
      return 1.0;
  }
}

const PlyProperty* PlyElement::find(const std::string& wanted) const {
  for (const PlyProperty& p : properties)
    if (p.name == wanted) return &p;
  return nullptr;
}

const PlyElement* PlyFile::find(const std::string& wanted) const {
  for (const PlyElement& e : elements)
    if (e.name == wanted) return &e;
  return nullptr;
}

PlyFile parsePly(const std::vector<char>& bytes, const std::string& path) { return PlyParser(bytes, path).parse(); }

PlyFile readPly(const std::string& path) { return parsePly(readInputFile(path, "a PLY file"), path); }

}  // namespace radview
