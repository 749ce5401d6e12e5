// .npy arrays (core/npy_array.h): what radview writes reads back exactly and has numpy's layout;
// what it refuses, it refuses naming the file and the fault. numpy's own files (float32 and
// float64, format 1.0 and 2.0) are read by tests/core/npy_numpy.py through `radview sample`.
#include "core/npy_array.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace radview {
namespace {

NpyMatrix example() {
  NpyMatrix m;
  m.rows = 2;
  m.columns = 3;
  m.values = {0.1, -2.5, 1e300, std::numeric_limits<double>::denorm_min(), 0.0, -0.0};
  return m;
}

TEST(NpyArray, WrittenArraysReadBackExactlyWithTheDataOnA64ByteBoundary) {
  const std::string bytes = npyBytes(example());
  ASSERT_EQ(bytes.compare(0, 8, std::string("\x93NUMPY\x01\x00", 8)), 0);
  const size_t headerBytes = uint8_t(bytes[8]) | size_t(uint8_t(bytes[9])) << 8;
  EXPECT_EQ((10 + headerBytes) % 64, 0u);
  EXPECT_EQ(bytes[10 + headerBytes - 1], '\n');
  EXPECT_NE(bytes.find("'shape': (2, 3)"), std::string::npos);
  const NpyMatrix back = parseNpy(bytes.data(), bytes.size(), "t.npy");
  ASSERT_EQ(back.rows, 2u);
  ASSERT_EQ(back.columns, 3u);
  for (size_t i = 0; i < 6; ++i) EXPECT_EQ(std::memcmp(&back.values[i], &example().values[i], 8), 0) << i;
}

// A header as numpy writes it, then `data`.
std::string npy(const std::string& dict, const std::string& data, char version = 1) {
  std::string out("\x93NUMPY", 6);
  out += version;
  out += '\0';
  const std::string header = dict + "\n";
  out += char(header.size());
  out += '\0';
  if (version != 1) out += std::string(2, '\0');
  return out + header + data;
}

std::string floats(std::initializer_list<float> values) {
  std::string out(values.size() * 4, '\0');
  std::memcpy(&out[0], values.begin(), out.size());
  return out;
}

TEST(NpyArray, Float32OneDimensionalAndVersionTwoArraysAreRead) {
  const std::string one = npy("{'descr': '<f4', 'fortran_order': False, 'shape': (3,), }", floats({1.5f, 2.0f, -3.25f}));
  const NpyMatrix row = parseNpy(one.data(), one.size(), "row.npy");
  EXPECT_EQ(row.rows, 1u);
  EXPECT_EQ(row.columns, 3u);
  EXPECT_EQ(row.values, (std::vector<double>{1.5, 2.0, -3.25}));
  const std::string two = npy("{'shape': (2, 1), 'fortran_order': False, 'descr': '<f4'}", floats({4.0f, 5.0f}), 2);
  const NpyMatrix column = parseNpy(two.data(), two.size(), "column.npy");
  EXPECT_EQ(column.rows, 2u);
  EXPECT_EQ(column.values, (std::vector<double>{4.0, 5.0}));
}

TEST(NpyArray, BadArraysAreRefusedNamingTheFileAndTheFault) {
  const std::string data = floats({1, 2, 3, 4});
  const std::pair<std::string, std::string> cases[] = {
      {"not numpy at all", "does not start with"},
      {npy("{'descr': '<i4', 'fortran_order': False, 'shape': (4,), }", data), "'<i4' numbers"},
      {npy("{'descr': '>f4', 'fortran_order': False, 'shape': (4,), }", data), "'>f4' numbers"},
      {npy("{'descr': '<f4', 'fortran_order': True, 'shape': (2, 2), }", data), "Fortran order"},
      {npy("{'descr': '<f4', 'fortran_order': False, 'shape': (1, 2, 2), }", data), "3 dimensions"},
      {npy("{'descr': '<f4', 'fortran_order': False, 'shape': (), }", data), "0 dimensions"},
      {npy("{'descr': '<f4', 'fortran_order': False, 'shape': (5,), }", data), "cut off"},
      {npy("{'descr': '<f4', 'fortran_order': False, 'shape': (3,), }", data), "16 bytes of data where its shape asks for 12"},
      {npy("{'descr': '<f4', 'fortran_order': False, 'shape': (99999999999999999999999,), }", data), "too large"},
      {npy("{'descr': '<f4', 'fortran_order': False, 'shape': (4,), 'extra': 1}", data), "unknown key 'extra'"},
      {npy("{'descr': '<f4', 'shape': (4,), }", data), "lacks descr, fortran_order or shape"},
      {npy("{'descr': '<f4, 'fortran_order': False, 'shape': (4,), }", data), "expected ','"},
      {npy("{'descr': '<f4', 'fortran_order': False, 'shape': (4,), }", data, 4), "format version 4"},
      {std::string("\x93NUMPY\x01\x00\xff\x00{", 11), "runs past the end"},
  };
  for (const auto& [bytes, fault] : cases) {
    try {
      parseNpy(bytes.data(), bytes.size(), "points.npy");
      ADD_FAILURE() << "accepted: " << fault;
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()).rfind("points.npy: ", 0), 0u) << e.what();
      EXPECT_NE(std::string(e.what()).find(fault), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace radview
