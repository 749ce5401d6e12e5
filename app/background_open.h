#pragma once
// Opening a file beside the viewer's frame loop: a worker reads it and, for a scene, meshes and
// lights it (openForViewing), then prepares it for drawing (gl::prepareMesh), while the window
// keeps drawing the file it shows and the panel says how long the opening has taken; the frame
// loop then only uploads the result. At 10^6 elements reading, meshing and preparing take
// seconds, during which the window would otherwise freeze.
#include "gl/prepared_mesh.h"
#include "solve/viewed_file.h"

#include <chrono>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace radview {

class BackgroundOpen {
 public:
  BackgroundOpen() = default;
  ~BackgroundOpen();  // waits for the worker (openForViewing cannot be interrupted)
  BackgroundOpen(const BackgroundOpen&) = delete;
  BackgroundOpen& operator=(const BackgroundOpen&) = delete;

  // Starts opening `path`. Asked while another opening is under way, the newer request wins:
  // it starts when that one ends, whose result is dropped.
  // `import` says how other tools' meshes are read (the viewer's --colours, --read-as, ...).
  void start(const std::string& path, double elementSize, const ImportOptions& import = {});
  bool running() const;

  struct Result {
    std::string path;
    std::optional<ViewedFile> viewed;  // and prepared, its mesh for MeshRenderer::adoptMesh; or, when it failed:
    std::optional<gl::PreparedMesh> prepared;
    std::string error;
  };
  // A finished opening, handed out once; nothing while one is under way.
  std::optional<Result> take();
  // "opening PATH ... 2.3 s" while one is under way, else empty.
  std::string status() const;

 private:
  void launch(const std::string& path);

  double elementSize_ = 0.0;
  ImportOptions import_;
  std::thread worker_;
  mutable std::mutex mutex_;  // guards the fields below
  bool busy_ = false;
  std::string path_;                    // the opening under way
  std::optional<std::string> pending_;  // the request that waits for it
  std::optional<Result> finished_;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace radview
