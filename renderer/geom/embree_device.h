#pragma once
// An Embree 3 device whose errors become radview's: Embree reports them through a callback,
// which keeps the first message for the Error that check() throws. The ray caster's BVH
// (visibility, C&W eq. 4.3) and the surface locator's (points to elements) live on one each.
#include <embree3/rtcore.h>

#include <mutex>
#include <string>

namespace radview {

class EmbreeDevice {
 public:
  // `user` names the work in error messages ("ray casting"). Throws Error if Embree cannot
  // create a device.
  explicit EmbreeDevice(std::string user);
  ~EmbreeDevice();
  EmbreeDevice(const EmbreeDevice&) = delete;
  EmbreeDevice& operator=(const EmbreeDevice&) = delete;

  RTCDevice get() const { return device_; }
  // Throws Error("<user>: <what> failed: <Embree's message>") if Embree has reported an error.
  void check(const char* what);

 private:
  std::string user_;
  std::mutex mutex_;
  std::string message_;  // Embree's first error, guarded by mutex_
  RTCDevice device_ = nullptr;
  static void record(void* self, RTCError code, const char* text);
};

}  // namespace radview
