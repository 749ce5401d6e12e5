#include "core/limits.h"

#include "core/error.h"

namespace radview {

void checkLimit(const std::string& where, uint64_t value, uint64_t limit, const std::string& what) {
  if (value > limit)
    throw Error(where, std::to_string(value) + " " + what + ", more than radview's limit of " + std::to_string(limit));
}

}  // namespace radview
