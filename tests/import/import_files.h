#pragma once
// Files the importer tests write: bytes to a fresh path under the test temp folder, and PLY
// bodies built value by value in either byte order.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

namespace radview::test {

// In a folder of the running test's own: ctest runs tests in parallel processes.
inline std::string writeTestFile(const std::string& name, const std::string& bytes) {
  const testing::TestInfo* test = testing::UnitTest::GetInstance()->current_test_info();
  const std::string owner = test ? std::string(test->test_suite_name()) + "." + test->name() : "no-test";
  const std::filesystem::path folder = std::filesystem::path(testing::TempDir()) / "radview_import" / owner;
  std::filesystem::create_directories(folder);
  const std::string path = (folder / name).string();
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// A binary PLY body, written in the byte order of the file being made.
class PlyBody {
 public:
  explicit PlyBody(bool bigEndian) : bigEndian_(bigEndian) {}
  template <class T>
  PlyBody& put(T value) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    if (bigEndian_)
      for (size_t k = 0; k < sizeof(T) / 2; ++k) std::swap(raw[k], raw[sizeof(T) - 1 - k]);
    bytes_.append(raw, sizeof(T));
    return *this;
  }
  const std::string& bytes() const { return bytes_; }

 private:
  bool bigEndian_;
  std::string bytes_;
};

}  // namespace radview::test
