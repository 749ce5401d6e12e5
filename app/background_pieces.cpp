#include "app/background_pieces.h"

#include "core/error.h"

#include <cstdio>
#include <exception>

namespace radview {

gl::RenderSettings BackgroundPieces::frame(gl::MeshRenderer& renderer, const gl::RenderSettings& settings,
                                           uint64_t meshVersion, std::string& status) {
  const std::string key = std::to_string(int(settings.method)) + "/" + std::to_string(int(settings.cloughTocher)) +
                          "/" + std::to_string(meshVersion) + "/" + std::to_string(settings.repairTVertices) + "/" +
                          std::to_string(settings.splitLines);
  if (std::optional<Result> done = take()) {
    if (status.rfind("setting up ", 0) == 0) status.clear();
    try {
      if (!done->setup) throw Error(done->error);
      if (done->key == key) renderer.adoptPieces(*done->setup, settings.splitLines);
    } catch (const std::exception& e) {
      failed_ = done->key;
      status = e.what();
    }
  }
  gl::RenderSettings drawn = settings;
  if (key != failed_)
    if (std::function<gl::DeferredSetup()> job = renderer.piecesSetup(settings)) {
      start(std::move(job), key, methodName(settings.method));
      drawn.method = Method::Gouraud;
    }
  if (running()) status = this->status();
  return drawn;
}

void BackgroundPieces::start(std::function<gl::DeferredSetup()> job, const std::string& key, const std::string& label) {
  if (running()) return;
  key_ = key;
  label_ = label;
  started_ = std::chrono::steady_clock::now();
  job_ = std::async(std::launch::async, std::move(job));
}

std::optional<BackgroundPieces::Result> BackgroundPieces::take() {
  if (!running() || job_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
  Result result;
  result.key = key_;
  try {
    result.setup = job_.get();
  } catch (const std::exception& e) {
    result.error = e.what();
  }
  job_ = {};
  return result;
}

std::string BackgroundPieces::status() const {
  if (!running()) return {};
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  char elapsed[32];
  std::snprintf(elapsed, sizeof elapsed, "%.1f s", seconds);
  return "setting up " + label_ + " ... " + elapsed + " (Gouraud meanwhile)";
}

}  // namespace radview
