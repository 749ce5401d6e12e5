#pragma once
// Small text helpers shared by error messages, option lists and numbers read from text.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace radview {

// A multi-line message (a driver's shader log, a parser's errors) as one line: non-empty
// lines joined by "; ", cut at maxLength characters.
std::string oneLine(const std::string& text, size_t maxLength = 300);

// "a, b, c".
std::string joined(const std::vector<std::string>& items, const std::string& separator = ", ");

// A GL or EGL enum or error code as the headers spell it: 0x3009.
std::string hexCode(unsigned value);

// A finite decimal number that fills all of `text` ("1e-3", "+2.5"; not " 2", "0x10", "inf"),
// or nothing. The one way radview reads a number from text (options, point lists).
std::optional<double> parseFiniteNumber(std::string_view text);
// A decimal integer that fills all of `text` ("+7" allowed), or nothing, also past int64's range.
std::optional<int64_t> parseInteger(std::string_view text);

// The file extension in lower case, with its dot: "scene.GLB" -> ".glb".
std::string lowerExtension(const std::string& path);

}  // namespace radview
