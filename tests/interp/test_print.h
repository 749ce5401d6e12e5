#pragma once
// Values printed for failure messages in the interpolant tests.
#include "core/types.h"

#include <sstream>
#include <string>

namespace radview::test {

// A point, vector or colour (Vec3 and Rgb are one type), to full precision: gtest's << does
// not find radview's operator<< for glm types.
inline std::string str(const Vec3& v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

}  // namespace radview::test
