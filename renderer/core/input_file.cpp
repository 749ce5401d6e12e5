#include "core/input_file.h"

#include "core/error.h"
#include "core/limits.h"

#include <filesystem>
#include <fstream>

namespace radview {

namespace fs = std::filesystem;

uint64_t checkInputFile(const std::string& path, const std::string& kind) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec && ec != std::errc::no_such_file_or_directory) throw Error(path, ec.message());
  if (!fs::exists(status)) throw Error(path, "no such file");
  if (fs::is_directory(status)) throw Error(path, "is a directory, not " + kind);
  if (!fs::is_regular_file(status)) throw Error(path, "is not a regular file");
  const uintmax_t size = fs::file_size(path, ec);
  if (ec) throw Error(path, "cannot read the file size: " + ec.message());
  if (size == 0) throw Error(path, "the file is empty");
  checkLimit(path, size, kMaxFileBytes, "bytes");
  return size;
}

std::vector<char> readInputFile(const std::string& path, const std::string& kind) {
  const uint64_t size = checkInputFile(path, kind);
  std::vector<char> bytes(size);
  std::ifstream in(path, std::ios::binary);
  if (!in.read(bytes.data(), std::streamsize(size))) throw Error(path, "the file could not be read");
  return bytes;
}

}  // namespace radview
