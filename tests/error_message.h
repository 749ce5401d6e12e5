#pragma once
// What a call throws, as text, for tests that check radview's one-line error messages.
#include "core/error.h"

#include <functional>
#include <string>

namespace radview::test {

// The message of the Error that `call` throws; "(no error)" when it throws none.
inline std::string errorOf(const std::function<void()>& call) {
  try {
    call();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace radview::test
