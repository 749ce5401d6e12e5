#pragma once
// Setting up a C1 method's pieces per pixel beside the viewer's frame loop
// (MeshRenderer::piecesSetup): the triangulation and corner gradients take seconds at 10^6
// elements, during which the window would otherwise freeze. The frame loop draws Gouraud in the
// meantime, the panel says how long the set-up has taken, and the loop then adopts the result
// (MeshRenderer::adoptPieces, which uploads it).
#include "gl/mesh_renderer.h"
#include "gl/method_pieces.h"

#include <chrono>
#include <cstdint>
#include <functional>
#include <future>
#include <optional>
#include <string>

namespace radview {

class BackgroundPieces {
 public:
  // This frame's part, before renderer.render: adopts a finished set-up that is still wanted,
  // starts the one `settings` needs (for the mesh the renderer was given as `meshVersion`), and
  // returns the settings to draw with: `settings`, or Gouraud while their pieces are set up.
  // `status` gets the progress, and a failure's message (render() then builds the pieces
  // itself, and throws the same error).
  gl::RenderSettings frame(gl::MeshRenderer& renderer, const gl::RenderSettings& settings, uint64_t meshVersion,
                           std::string& status);

  // Starts `job`, which sets up the pieces named `key` (the method, its variant and the mesh
  // they are for), unless one is under way: one job at a time, as it cannot be interrupted.
  void start(std::function<gl::DeferredSetup()> job, const std::string& key, const std::string& label);
  bool running() const { return job_.valid(); }
  const std::string& key() const { return key_; }

  struct Result {
    std::string key;
    std::optional<gl::DeferredSetup> setup;  // or, when it failed:
    std::string error;
  };
  // The finished set-up, handed out once; nothing while one is under way.
  std::optional<Result> take();
  // "setting up clough-tocher ... 2.3 s" while one is under way, else empty.
  std::string status() const;

 private:
  std::future<gl::DeferredSetup> job_;  // its destructor waits for the job
  std::string key_, label_;
  std::string failed_;  // the key of a set-up that failed: not tried again in the background
  std::chrono::steady_clock::time_point started_;
};

}  // namespace radview
