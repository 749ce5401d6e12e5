#pragma once
// Small text helpers shared by error messages and option lists.
#include <string>
#include <vector>

namespace radview {

// A multi-line message (a driver's shader log, a parser's errors) as one line: non-empty
// lines joined by "; ", cut at maxLength characters.
std::string oneLine(const std::string& text, size_t maxLength = 300);

// "a, b, c".
std::string joined(const std::vector<std::string>& items, const std::string& separator = ", ");

// A GL or EGL enum or error code as the headers spell it: 0x3009.
std::string hexCode(unsigned value);

// The file extension in lower case, with its dot: "scene.GLB" -> ".glb".
std::string lowerExtension(const std::string& path);

}  // namespace radview
