#pragma once
// Scenes for the final gather's tests, each with an answer known in closed form.
#include "core/camera.h"
#include "core/image.h"
#include "mesh/radiosity_mesh.h"
#include "mesh/uniform_mesher.h"
#include "scene/scene.h"
#include "trace/camera_rays.h"
#include "trace/form_factor.h"

#include <cmath>
#include <vector>

namespace radview::test {

// A 4 x 4 receiver (rho 0.5) at z = 0 facing +z, under a unit square emitter at z = 1 facing
// it (E 1, rho 0): the receiver's radiosity is rho E F(x -> emitter), nothing else.
inline Scene receiverUnderSquareEmitter() {
  Scene scene;
  scene.materials = {{"receiver", {0.5, 0.5, 0.5}, {0, 0, 0}}, {"emitter", {0, 0, 0}, {1, 1, 1}}};
  scene.polygons.push_back({{{-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}}, 0});
  scene.polygons.push_back({{{-0.5, -0.5, 1}, {-0.5, 0.5, 1}, {0.5, 0.5, 1}, {0.5, -0.5, 1}}, 1});
  return scene;
}

// The scene meshed with its exact solution where eq. 9.9 needs one: B^ = E on the emitter (it
// reflects nothing), which the receiver's indirect rays meet as B^ - E = 0.
inline RadiosityMesh receiverUnderSquareEmitterMesh() {
  const Scene scene = receiverUnderSquareEmitter();
  RadiosityMesh mesh = meshUniformly(scene, 0.5);
  for (const Element& e : mesh.elements)
    for (uint32_t n : e.corners) mesh.nodes[n].B = mesh.materials[size_t(e.material)].E;
  return mesh;
}

// The receiver seen obliquely from below the emitter's height: most pixels see the receiver,
// some the emitter's face.
inline Camera receiverCamera() {
  Camera camera;
  camera.eye = {0.0, -3.5, 0.6};
  camera.target = {0.0, 0.0, 0.0};
  camera.up = {0.0, 0.0, 1.0};
  camera.yfov = glm::radians(45.0);
  return camera;
}

// Straight down on the emitter's back, which hides the receiver's centre.
inline Camera emitterBackCamera() {
  Camera camera;
  camera.eye = {0.0, 0.0, 3.0};
  camera.target = {0.0, 0.0, 0.0};
  camera.yfov = glm::radians(10.0);
  return camera;
}

// Inside the unit furnace box (tests/solve/solver_scenes.h), looking at a corner of its floor.
inline Camera furnaceCamera() {
  Camera camera;
  camera.eye = {0.5, 0.5, 0.95};
  camera.target = {0.3, 0.4, 0.0};
  camera.yfov = glm::radians(100.0);
  return camera;
}

// The receiver's radiosity rho E F(x -> emitter), F by Lambert's formula, averaged over each
// pixel of a view of it (what jittered eye rays converge to) by the midpoint rule on an 8 x 8
// grid, far below what an estimator leaves at 64 spp; or a negative value where part of the
// pixel (a 5 x 5 lattice of it, corners included) does not see the receiver.
inline std::vector<double> expectedReceiverRadiosity(const Camera& camera, int width, int height) {
  const Scene scene = receiverUnderSquareEmitter();
  const CameraRays rays(camera, width, height);
  const double rhoE = scene.materials[0].rho.r * scene.materials[1].E.r;
  // Where the ray through (px, py) meets the receiver's plane z = 0, and whether it sees the
  // receiver there (within it, and not behind the emitter, whose face hides the receiver where
  // the ray crosses z = 1 inside it first).
  auto receiverPoint = [&](double px, double py, Vec3& p) {
    const Ray ray = rays.through(px, py);
    const double t = -ray.origin.z / ray.direction.z;
    p = ray.origin + t * ray.direction;
    const double tEmitter = (1.0 - ray.origin.z) / ray.direction.z;
    const Vec3 q = ray.origin + tEmitter * ray.direction;
    const bool hidden = tEmitter > 0 && tEmitter < t && std::abs(q.x) <= 0.5 && std::abs(q.y) <= 0.5;
    return t > 0 && std::abs(p.x) < 2 && std::abs(p.y) < 2 && !hidden;
  };
  std::vector<double> expected(size_t(width) * size_t(height), -1.0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      bool receiver = true;
      Vec3 p;
      for (int k = 0; k < 25 && receiver; ++k) receiver = receiverPoint(x + (k % 5) / 4.0, y + (k / 5) / 4.0, p);
      if (!receiver) continue;
      double sum = 0.0;
      for (int k = 0; k < 64; ++k) {
        receiverPoint(x + (k % 8 + 0.5) / 8.0, y + (k / 8 + 0.5) / 8.0, p);
        sum += rhoE * pointToPolygonFormFactor(p, {0, 0, 1}, scene.polygons[1].vertices);
      }
      expected[size_t(y) * size_t(width) + size_t(x)] = sum / 64.0;
    }
  return expected;
}

struct ErrorFigures {
  double rmse = 0.0, meanSigned = 0.0, meanExpected = 0.0;
  size_t pixels = 0;
};

inline ErrorFigures errorAgainst(const LinearImage& image, const std::vector<double>& expected) {
  ErrorFigures f;
  double squared = 0.0;
  for (size_t i = 0; i < expected.size(); ++i) {
    if (expected[i] < 0.0) continue;
    const double d = image.rgba[4 * i] - expected[i];
    squared += d * d;
    f.meanSigned += d;
    f.meanExpected += expected[i];
    ++f.pixels;
  }
  f.rmse = std::sqrt(squared / double(f.pixels));
  f.meanSigned /= double(f.pixels);
  f.meanExpected /= double(f.pixels);
  return f;
}

}  // namespace radview::test
