#pragma once
// The checks every reader makes before it trusts a path the user named: that it exists, is a
// regular file (not a directory, a FIFO or /dev/zero), is not empty and not larger than
// kMaxFileBytes.
#include <cstdint>
#include <string>
#include <vector>

namespace radview {

// Returns the file's size. Throws Error(path, ...) saying which check failed; `kind` names what
// was expected ("a glTF file"), for the directory case.
uint64_t checkInputFile(const std::string& path, const std::string& kind);

// checkInputFile, then the whole file. Throws Error(path, ...).
std::vector<char> readInputFile(const std::string& path, const std::string& kind);

}  // namespace radview
