#pragma once
// One exception type for everything that is the input's or the environment's fault (a bad
// file, a shader that does not compile, no EGL display). Programmer mistakes use RADVIEW_CHECK.
// Only app/ catches Error: it prints what() on one line and exits non-zero.
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace radview {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
  // "FILE: what is wrong" - the form every file error takes.
  Error(const std::string& file, const std::string& problem) : std::runtime_error(file + ": " + problem) {}
};

}  // namespace radview

// Always-on invariant check: prints the condition and where, then aborts.
#define RADVIEW_CHECK(cond)                                                                  \
  do {                                                                                       \
    if (!(cond)) {                                                                           \
      std::fprintf(stderr, "%s:%d: internal check failed: %s\n", __FILE__, __LINE__, #cond); \
      std::abort();                                                                          \
    }                                                                                        \
  } while (0)
