#include "app/background_open.h"

#include <cstdio>
#include <exception>
#include <memory>

namespace radview {

BackgroundOpen::~BackgroundOpen() {
  if (worker_.joinable()) worker_.join();
}

void BackgroundOpen::start(const std::string& path, double elementSize, const ImportOptions& import) {
  std::unique_lock<std::mutex> lock(mutex_);
  elementSize_ = elementSize;
  import_ = import;
  if (busy_) {
    pending_ = path;
    return;
  }
  lock.unlock();
  launch(path);
}

void BackgroundOpen::launch(const std::string& path) {
  if (worker_.joinable()) worker_.join();  // finished: busy_ is false
  const std::lock_guard<std::mutex> lock(mutex_);
  busy_ = true;
  path_ = path;
  finished_.reset();
  started_ = std::chrono::steady_clock::now();
  worker_ = std::thread([this, path, elementSize = elementSize_, import = import_] {
    Result result;
    result.path = path;
    try {
      result.viewed = openForViewing(path, elementSize, import, kDirectLight);
      gl::PrepareOptions options;
      options.triangles = true;  // off the frame loop, as the rest
      result.prepared = gl::prepareMesh(std::make_shared<const RadiosityMesh>(result.viewed->mesh), options);
    } catch (const std::exception& e) {
      result.error = e.what();
    }
    const std::lock_guard<std::mutex> done(mutex_);
    finished_ = std::move(result);
    busy_ = false;
  });
}

bool BackgroundOpen::running() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return busy_ || pending_.has_value();
}

std::optional<BackgroundOpen::Result> BackgroundOpen::take() {
  std::unique_lock<std::mutex> lock(mutex_);
  if (busy_ || !finished_) return std::nullopt;
  if (pending_) {  // superseded: open the newer request instead
    const std::string next = *pending_;
    pending_.reset();
    finished_.reset();
    lock.unlock();
    launch(next);
    return std::nullopt;
  }
  std::optional<Result> out = std::move(finished_);
  finished_.reset();
  return out;
}

std::string BackgroundOpen::status() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!busy_ && !pending_) return {};
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  char elapsed[32];
  std::snprintf(elapsed, sizeof elapsed, "%.1f s", seconds);
  return "opening " + path_ + " ... " + elapsed + (pending_ ? " (then " + *pending_ + ")" : std::string());
}

}  // namespace radview
