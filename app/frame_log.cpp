#include "app/frame_log.h"

#include "core/error.h"
#include "interp/method_registry.h"

#include <cerrno>
#include <chrono>
#include <cstring>

namespace radview {

FrameLog::FrameLog(const std::string& path) : file_(std::fopen(path.c_str(), "w")), path_(path) {
  if (!file_) throw Error(path, std::string("cannot write the frame log: ") + std::strerror(errno));
  std::fprintf(file_, "# frame end_s cpu_ms wanted drawn mesh_version\n");
  std::fflush(file_);
}

FrameLog::~FrameLog() { std::fclose(file_); }

void FrameLog::record(int frame, double cpuMs, Method wanted, Method drawn, uint64_t meshVersion) {
  // Seconds since the epoch: the clock the driving script reads with `date +%s.%N`.
  const double end = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  std::fprintf(file_, "%d %.6f %.3f %s %s %llu\n", frame, end, cpuMs, methodName(wanted).c_str(),
               methodName(drawn).c_str(), static_cast<unsigned long long>(meshVersion));
  std::fflush(file_);
}

}  // namespace radview
