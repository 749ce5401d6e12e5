#include "core/memory_budget.h"

#include "core/error.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

namespace radview {

namespace {

constexpr const char* kOverrideVariable = "RADVIEW_MAX_MEMORY";

// /proc/meminfo's "MemAvailable:  N kB".
std::optional<uint64_t> memAvailable() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key, unit;
  uint64_t value = 0;
  while (meminfo >> key >> value) {
    std::getline(meminfo, unit);
    if (key == "MemAvailable:") return value * 1024;
  }
  return std::nullopt;
}

// A number from a cgroup v2 file of this process's cgroup; empty for "max" or when absent.
std::optional<uint64_t> cgroupValue(const std::string& file) {
  std::ifstream self("/proc/self/cgroup");
  std::string line, path;
  while (std::getline(self, line))
    if (line.rfind("0::", 0) == 0) path = line.substr(3);  // v2: the single "0::PATH" line
  if (path.empty()) return std::nullopt;
  std::ifstream in("/sys/fs/cgroup" + path + "/" + file);
  uint64_t value = 0;
  if (!(in >> value)) return std::nullopt;
  return value;
}

// "1.8 GiB", or "768 MiB" below a GiB.
std::string readable(uint64_t bytes) {
  char text[32];
  if (bytes >= uint64_t(1) << 30)
    std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(uint64_t(1) << 30));
  else
    std::snprintf(text, sizeof text, "%.0f MiB", double(bytes) / double(uint64_t(1) << 20));
  return text;
}

}  // namespace

std::optional<uint64_t> parseByteSize(const std::string& text) {
  size_t digits = 0;
  while (digits < text.size() && digits < 19 && text[digits] >= '0' && text[digits] <= '9') ++digits;
  if (digits == 0) return std::nullopt;
  const std::string suffix = text.substr(digits);
  int shift = 0;
  if (suffix == "K" || suffix == "k")
    shift = 10;
  else if (suffix == "M" || suffix == "m")
    shift = 20;
  else if (suffix == "G" || suffix == "g")
    shift = 30;
  else if (!suffix.empty())
    return std::nullopt;
  const uint64_t value = std::stoull(text.substr(0, digits));
  if (value > (std::numeric_limits<uint64_t>::max() >> shift)) return std::nullopt;
  return value << shift;
}

std::optional<uint64_t> availableMemoryBytes() {
  if (const char* override = std::getenv(kOverrideVariable)) {
    const std::optional<uint64_t> bytes = parseByteSize(override);
    if (!bytes)
      throw Error(std::string(kOverrideVariable) + "='" + override +
                  "': expected a size in bytes, or with a K, M or G suffix (e.g. 8G)");
    return bytes;
  }
  std::optional<uint64_t> available = memAvailable();
  const std::optional<uint64_t> max = cgroupValue("memory.max"), current = cgroupValue("memory.current");
  if (max && current) {
    const uint64_t cgroupLeft = *max > *current ? *max - *current : 0;
    available = available ? std::min(*available, cgroupLeft) : cgroupLeft;
  }
  return available;
}

void checkMemory(const std::string& where, const std::string& what, uint64_t bytes, std::optional<uint64_t> available) {
  if (!available || bytes <= *available) return;
  const bool overridden = std::getenv(kOverrideVariable) != nullptr;
  throw Error(where,
              "needs about " + readable(bytes) + " of memory for " + what + ", more than the " + readable(*available) +
                  (overridden ? " that " + std::string(kOverrideVariable) + " allows" : " this machine has available") +
                  "; use a smaller size");
}

}  // namespace radview
