#pragma once
// How much memory radview may plan to use, and the check that keeps an image-sized allocation
// from exhausting the machine. The fixed limits (core/limits.h) bound what any input can ask
// for; an image at the largest --size still needs more memory than many machines have (a bench
// view of 16384 x 16384 needs about 40 GB), so what scales with the image is checked against
// the memory actually available before anything is allocated.
#include <cstdint>
#include <optional>
#include <string>

namespace radview {

// Bytes per pixel each kind of image work needs at its peak: the growth of the peak resident
// set between two image sizes of the Cornell box (`/usr/bin/time -f %M`), rounded up by about a
// quarter. They are estimates for the check below, not promises.
inline constexpr uint64_t kRenderBytesPerPixel = 40;       // GL render to PNG
inline constexpr uint64_t kComparisonBytesPerPixel = 112;  // --view difference or --linear-out
inline constexpr uint64_t kGatherBytesPerPixel = 112;      // the final gather (also the viewer's)
// bench: the reference's runs and sums, every row's values (8 a row), the error split's (32 a
// split row) and the renders, for the default rows.
inline constexpr uint64_t kBenchBytesPerPixel = 1024;

// The bytes radview may plan to use: RADVIEW_MAX_MEMORY when set (bytes, or with a K, M or G
// suffix: powers of 1024), else what the kernel reports available without swapping
// (MemAvailable), lowered to what the process's cgroup (v2) still allows. Empty when none of
// these can be read. Throws Error for a RADVIEW_MAX_MEMORY that is not such a size.
std::optional<uint64_t> availableMemoryBytes();

// Parses "123", "512K", "64M", "2G" (powers of 1024) to bytes; empty if `text` is not one.
std::optional<uint64_t> parseByteSize(const std::string& text);

// Throws Error(where, "needs about X GiB of memory for <what>, more than the Y GiB available
// ...") when bytes > available. Does nothing when available is empty (unknown).
void checkMemory(const std::string& where, const std::string& what, uint64_t bytes,
                 std::optional<uint64_t> available = availableMemoryBytes());

}  // namespace radview
