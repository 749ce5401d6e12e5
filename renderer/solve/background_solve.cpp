#include "solve/background_solve.h"

#include "mesh/topology.h"

#include <chrono>
#include <cstdio>

namespace radview {

namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kPublishEvery = std::chrono::milliseconds(250);

std::string describe(const char* phase, const SolveProgress& p, size_t tVertices) {
  char text[256];
  std::snprintf(text, sizeof text, "%s: %zu shots, unshot %.2f%%, %zu elements, %zu T-vertices, %.1fM rays/s", phase,
                p.shots, 100.0 * p.unshotFraction, p.elements, tVertices, p.raysPerSecond() * 1e-6);
  return text;
}

}  // namespace

BackgroundSolve::~BackgroundSolve() { cancel(); }

void BackgroundSolve::start(const Scene& scene, const SolveSettings& settings) {
  cancel();
  cancelled_ = false;
  running_ = true;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    status_ = "solving: meshing the patches";
  }
  worker_ = std::thread(&BackgroundSolve::run, this, scene, settings);
}

void BackgroundSolve::cancel() {
  cancelled_ = true;
  if (worker_.joinable()) worker_.join();
}

void BackgroundSolve::abandon() {
  cancel();
  std::lock_guard<std::mutex> lock(mutex_);
  latest_.reset();
  status_.clear();
}

std::optional<RadiosityMesh> BackgroundSolve::takeSolution() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::optional<RadiosityMesh> out = std::move(latest_);
  latest_.reset();
  return out;
}

std::string BackgroundSolve::status() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return status_;
}

void BackgroundSolve::publish(RadiosityMesh mesh, const std::string& status) {
  std::lock_guard<std::mutex> lock(mutex_);
  latest_ = std::move(mesh);
  status_ = status;
}

// RadiositySolve's steps, with a look at the clock and the cancel flag between them: the
// partial solution is published at most every kPublishEvery while shooting, and before every
// round of subdivision.
void BackgroundSolve::run(Scene scene, SolveSettings settings) {
  try {
    RadiositySolve solve(scene, settings);
    // Whether the subdivision is for the view, or why a view asked for was left out.
    std::string viewNote;
    if (!settings.subdivision.views.empty()) {
      const SolveSummary summary = solve.summary();
      viewNote = summary.viewWarnings.empty() ? "; meshed for the view" : "; " + summary.viewWarnings.front();
    }
    auto last = Clock::now();
    auto show = [&](const char* phase) {
      RadiosityMesh mesh = solve.solution();
      const size_t tVertices = MeshTopology(mesh).tVertices().size();
      publish(std::move(mesh), describe(phase, solve.progress(), tVertices) + viewNote);
      last = Clock::now();
    };
    show("shooting");
    while (!cancelled_ && solve.step()) {
      if (solve.phase() == RadiositySolve::Phase::Subdividing)
        show("subdividing");
      else if (Clock::now() - last > kPublishEvery)
        show("shooting");
    }
    show(cancelled_ ? "cancelled" : "solved");
  } catch (const std::exception& e) {
    std::lock_guard<std::mutex> lock(mutex_);
    status_ = std::string("solve failed: ") + e.what();
  }
  running_ = false;
}

}  // namespace radview
