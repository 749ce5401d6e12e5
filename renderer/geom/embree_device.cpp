#include "geom/embree_device.h"

#include "core/error.h"

namespace radview {

EmbreeDevice::EmbreeDevice(std::string user) : user_(std::move(user)) {
  device_ = rtcNewDevice(nullptr);
  if (!device_) throw Error(user_ + ": Embree could not create a device");
  rtcSetDeviceErrorFunction(device_, &EmbreeDevice::record, this);
}

EmbreeDevice::~EmbreeDevice() { rtcReleaseDevice(device_); }

void EmbreeDevice::record(void* self, RTCError code, const char* text) {
  auto* device = static_cast<EmbreeDevice*>(self);
  const std::lock_guard<std::mutex> lock(device->mutex_);
  if (device->message_.empty())
    device->message_ = "Embree error " + std::to_string(int(code)) + (text ? std::string(": ") + text : std::string());
}

void EmbreeDevice::check(const char* what) {
  const RTCError code = rtcGetDeviceError(device_);
  const std::lock_guard<std::mutex> lock(mutex_);
  if (code == RTC_ERROR_NONE && message_.empty()) return;
  throw Error(user_ + ": " + what +
              " failed: " + (message_.empty() ? "Embree error " + std::to_string(int(code)) : message_));
}

}  // namespace radview
