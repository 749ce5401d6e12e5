#pragma once
// The one way radview spreads a loop over the machine's cores.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace radview {

// The number of threads parallelFor uses: every core, at least one.
inline unsigned workerCount() { return std::max(1u, std::thread::hardware_concurrency()); }

// Runs body(i) for every i in [0, count), on workerCount() threads that take blocks of
// `block` indices from a shared counter. The order is unspecified: body must make each i's
// result independent of which thread runs it (deterministic results need that anyway).
// Where body throws, the exception of the lowest such i is rethrown once all threads are
// done (indices above it are skipped), as a plain loop would have thrown it.
template <typename Body>
void parallelFor(size_t count, const Body& body, size_t block = 256) {
  std::atomic<size_t> next{0}, failedAt{SIZE_MAX};
  std::mutex failure;
  std::exception_ptr error;
  auto work = [&] {
    for (size_t begin = next.fetch_add(block); begin < count; begin = next.fetch_add(block))
      for (size_t i = begin; i < std::min(count, begin + block) && i < failedAt.load(std::memory_order_relaxed); ++i) {
        try {
          body(i);
        } catch (...) {
          const std::lock_guard<std::mutex> lock(failure);
          if (i < failedAt) {
            failedAt = i;
            error = std::current_exception();
          }
        }
      }
  };
  std::vector<std::thread> helpers;
  for (unsigned t = 1; t < workerCount() && t * block < count; ++t) helpers.emplace_back(work);
  work();
  for (std::thread& helper : helpers) helper.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace radview
