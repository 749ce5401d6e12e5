#pragma once
// Values printed for failure messages: radview's points, vectors and colours (glm vectors) to
// full precision, as text (str) and in gtest's own messages (EXPECT_EQ(a, b) prints both sides).
#include "core/types.h"

#include <ostream>
#include <sstream>
#include <string>

namespace radview::test {

// A point, vector or colour (Vec3 and Rgb are one type), to full precision.
inline std::string str(const Vec3& v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

}  // namespace radview::test

namespace glm {

// Found by gtest through argument-dependent lookup: radview's operator<< lives in namespace
// radview, where gtest's printer does not look.
inline void PrintTo(const dvec3& v, std::ostream* os) { *os << radview::test::str(v); }

}  // namespace glm
