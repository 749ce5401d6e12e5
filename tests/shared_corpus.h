// Tests that read the third-party corpora in ../shared, beside the checkout. A user's clone has
// no ../shared: there such a test is skipped and says why (ctest lists it as Skipped, label
// `corpus`). CI lays ../shared beside its clone and sets CI=true: there a missing corpus is a
// failure, so that these tests can never pass silently by not running.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace radview::test {

inline bool corpusRequired() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && std::string(ci) == "true";
}

inline std::string corpusMissing(const std::filesystem::path& path) {
  return "no shared corpus at " + path.string() +
         " (the third-party corpora are not in the repository: they lie in ../shared beside the checkout)";
}

}  // namespace radview::test

// Skips the test, or under CI fails it, where `location` does not exist. A macro because both
// GTEST_SKIP and FAIL return from the test body.
#define RADVIEW_REQUIRE_SHARED_CORPUS(location)                                                            \
  do {                                                                                                     \
    const std::filesystem::path radviewCorpusPath_ = (location);                                           \
    if (!std::filesystem::exists(radviewCorpusPath_)) {                                                    \
      if (::radview::test::corpusRequired())                                                               \
        FAIL() << ::radview::test::corpusMissing(radviewCorpusPath_) << "; with CI=true it must be there"; \
      GTEST_SKIP() << ::radview::test::corpusMissing(radviewCorpusPath_);                                  \
    }                                                                                                      \
  } while (false)
