#pragma once
// A solve run beside a frame loop (the viewer's): a worker thread takes RadiositySolve's steps,
// the same as `radview solve`, and every quarter second publishes the partial solution (with
// the ambient term, Cohen et al. 1988, so it is shown at its final brightness from the first
// shots) for the window to draw, which stays responsive throughout; it can be cancelled
// between two steps.
#include "mesh/radiosity_mesh.h"
#include "scene/scene.h"
#include "solve/radiosity_solve.h"

#include <atomic>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace radview {

class BackgroundSolve {
 public:
  BackgroundSolve() = default;
  ~BackgroundSolve();  // cancels and waits
  BackgroundSolve(const BackgroundSolve&) = delete;
  BackgroundSolve& operator=(const BackgroundSolve&) = delete;

  // Starts solving a copy of `scene` (cancelling a solve under way).
  void start(const Scene& scene, const SolveSettings& settings);
  // Stops after the shot or subdivision round in progress; what was published stays.
  void cancel();
  // Cancels and forgets the solve: nothing it published is handed out any more.
  void abandon();
  bool running() const { return running_; }

  // The latest published solution, once per publication (nothing if none is new).
  std::optional<RadiosityMesh> takeSolution();
  // A line for the panel: phase, shots, unshot power, elements, T-vertices, rays/s; or the error.
  std::string status() const;

 private:
  void run(Scene scene, SolveSettings settings);
  void publish(RadiosityMesh mesh, const std::string& status);

  std::thread worker_;
  std::atomic<bool> running_{false}, cancelled_{false};
  mutable std::mutex mutex_;  // guards the fields below
  std::optional<RadiosityMesh> latest_;
  std::string status_;
};

}  // namespace radview
