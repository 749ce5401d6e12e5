// The memory check for image-sized work (core/memory_budget.h).
#include "core/memory_budget.h"

#include "tests/error_message.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace radview {
namespace {

// Sets RADVIEW_MAX_MEMORY for one test and restores what was there.
class MaxMemoryVariable {
 public:
  explicit MaxMemoryVariable(const char* value) {
    if (const char* old = std::getenv("RADVIEW_MAX_MEMORY")) old_ = old, hadOld_ = true;
    setenv("RADVIEW_MAX_MEMORY", value, 1);
  }
  ~MaxMemoryVariable() {
    if (hadOld_)
      setenv("RADVIEW_MAX_MEMORY", old_.c_str(), 1);
    else
      unsetenv("RADVIEW_MAX_MEMORY");
  }

 private:
  std::string old_;
  bool hadOld_ = false;
};

using test::errorOf;

TEST(MemoryBudget, ByteSizesTakeBinarySuffixes) {
  EXPECT_EQ(parseByteSize("0"), 0u);
  EXPECT_EQ(parseByteSize("123"), 123u);
  EXPECT_EQ(parseByteSize("512K"), 512u << 10);
  EXPECT_EQ(parseByteSize("64m"), uint64_t(64) << 20);
  EXPECT_EQ(parseByteSize("24G"), uint64_t(24) << 30);
  for (const char* bad : {"", "G", "-1", "1.5G", "8GB", "8 G", "1T", "99999999999999999999", "17179869184G"})
    EXPECT_FALSE(parseByteSize(bad).has_value()) << bad;
}

TEST(MemoryBudget, RefusesPastWhatIsAvailableNamingBoth) {
  const std::string message =
      errorOf([] { checkMemory("--size 4096x4096", "the final gather", uint64_t(1800) << 20, uint64_t(1) << 30); });
  EXPECT_EQ(message,
            "--size 4096x4096: needs about 1.8 GiB of memory for the final gather, more than the 1.0 GiB this machine "
            "has available; use a smaller size");
  EXPECT_EQ(errorOf([] { checkMemory("x", "y", uint64_t(1) << 30, uint64_t(1) << 30); }), "(no error)");
  EXPECT_EQ(errorOf([] { checkMemory("x", "y", ~uint64_t(0), std::nullopt); }), "(no error)") << "unknown: not checked";
}

TEST(MemoryBudget, TheMachineReportsWhatIsAvailable) {
  // Linux always has /proc/meminfo's MemAvailable; a cgroup can only lower it.
  const std::optional<uint64_t> available = availableMemoryBytes();
  ASSERT_TRUE(available.has_value());
  EXPECT_GT(*available, 0u);
}

TEST(MemoryBudget, TheVariableOverridesTheMachine) {
  {
    const MaxMemoryVariable variable("3G");
    EXPECT_EQ(availableMemoryBytes(), uint64_t(3) << 30);
    EXPECT_NE(errorOf([] {
                checkMemory("w", "z", uint64_t(4) << 30);
              }).find("than the 3.0 GiB that RADVIEW_MAX_MEMORY allows"),
              std::string::npos);
  }
  const MaxMemoryVariable variable("plenty");
  EXPECT_EQ(errorOf([] { availableMemoryBytes(); }),
            "RADVIEW_MAX_MEMORY='plenty': expected a size in bytes, or with a K, M or G suffix (e.g. 8G)");
}

}  // namespace
}  // namespace radview
