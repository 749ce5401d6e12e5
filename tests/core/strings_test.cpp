// Numbers read from text: what parseFiniteNumber and parseInteger take and refuse.
#include "core/strings.h"

#include <gtest/gtest.h>

#include <limits>

namespace radview {
namespace {

TEST(Strings, FiniteNumbersFillTheWholeText) {
  EXPECT_EQ(parseFiniteNumber("1e-3"), 1e-3);
  EXPECT_EQ(parseFiniteNumber("+2.5"), 2.5);
  EXPECT_EQ(parseFiniteNumber("-0.25"), -0.25);
  EXPECT_EQ(parseFiniteNumber("0.1"), 0.1) << "correctly rounded";
  for (const char* bad : {"", "+", "+-1", " 2", "2 ", "1,5", "0x10", "inf", "nan", "1e400", "abc", "1.2.3"})
    EXPECT_EQ(parseFiniteNumber(bad), std::nullopt) << "'" << bad << "'";
}

TEST(Strings, IntegersFillTheWholeTextAndStayInRange) {
  EXPECT_EQ(parseInteger("64"), 64);
  EXPECT_EQ(parseInteger("+7"), 7);
  EXPECT_EQ(parseInteger("-3"), -3);
  EXPECT_EQ(parseInteger("9223372036854775807"), std::numeric_limits<int64_t>::max());
  for (const char* bad : {"", "1.0", "1e3", " 1", "9223372036854775808", "12a", "+-1"})
    EXPECT_EQ(parseInteger(bad), std::nullopt) << "'" << bad << "'";
}

}  // namespace
}  // namespace radview
