#pragma once
// Scenes with a known answer: one bounce, no occlusion. A grey square receiver of reflectance
// rho under a square emitter of exitance E that reflects nothing; nothing else. Light reaches
// the receiver once and stops, so its radiosity is
//     B(x) = rho * E * F(x -> emitter),
// F the form factor from a differential area at x to the emitter polygon, by Lambert's formula
// (C&W §4.x, the contour integral for a polygon wholly above the receiver's horizon):
//     F = 1 / (2 pi) * sum over the emitter's edges i of  theta_i * n . (R_i x R_i+1) / |R_i x R_i+1|,
// R_i the vectors from x to the emitter's vertices (taken clockwise as seen from x, so that
// every term is positive for an emitter facing x), theta_i the angle between R_i and R_i+1.
// Written here from the formula, not with radview's own form factor code, so that tests hold
// the solver, the interpolants and the bench to an answer they did not compute.
#include "scene/scene.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <vector>

namespace radview::test {

struct ClosedFormScene {
  Scene scene;  // polygon 0 the receiver, polygon 1 the emitter
  Vec3 receiverNormal{0.0};
  Rgb rho{0.0}, E{0.0};  // the receiver's reflectance, the emitter's exitance

  // Lambert's formula at a point x of the receiver (see above).
  double formFactor(const Vec3& x) const {
    const std::vector<Vec3>& v = scene.polygons[1].vertices;
    double sum = 0.0;
    for (size_t i = 0; i < v.size(); ++i) {
      // The emitter's vertices are counter-clockwise about its front, which faces x: seen from
      // x they run clockwise, so R_i+1 x R_i is the edge's outward-from-x orientation.
      const Vec3 a = v[(i + 1) % v.size()] - x, b = v[i] - x;
      const Vec3 c = glm::cross(a, b);
      const double length = glm::length(c);
      if (length == 0.0) continue;
      const double theta = std::atan2(length, glm::dot(a, b));
      sum += theta * glm::dot(receiverNormal, c) / length;
    }
    return sum / (2.0 * 3.14159265358979323846);
  }
  // The exact radiosity at a point of the receiver.
  Rgb B(const Vec3& x) const { return rho * E * formFactor(x); }
};

// The receiver: the unit square in the plane y = 0, facing +y. The emitter: a square of side
// `emitterSide` centred over (0.5, height, 0.5), facing the receiver, turned by `tiltDegrees`
// about the x axis (0: parallel to the receiver). For tilts up to about 60 degrees at the
// default size and height, every point of the receiver sees the whole emitter in front of it.
inline ClosedFormScene emitterOverSquare(double tiltDegrees = 0.0, double emitterSide = 0.2, double height = 0.5) {
  ClosedFormScene s;
  s.rho = Rgb(0.5, 0.6, 0.7);
  s.E = Rgb(10.0, 10.0, 10.0);
  s.receiverNormal = Vec3(0.0, 1.0, 0.0);
  s.scene.materials = {{"receiver", s.rho, Rgb(0.0)}, {"emitter", Rgb(0.0), s.E}};
  s.scene.polygons.push_back({{{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}}, 0});
  const double a = 0.5 * emitterSide;
  const glm::dmat4 turn = glm::translate(glm::dmat4(1.0), Vec3(0.5, height, 0.5)) *
                          glm::rotate(glm::dmat4(1.0), glm::radians(tiltDegrees), Vec3(1.0, 0.0, 0.0));
  std::vector<Vec3> emitter;
  for (const Vec3& corner : {Vec3(-a, 0, -a), Vec3(a, 0, -a), Vec3(a, 0, a), Vec3(-a, 0, a)})
    emitter.push_back(Vec3(turn * glm::dvec4(corner, 1.0)));  // faces -y before the turn
  s.scene.polygons.push_back({emitter, 1});
  return s;
}

}  // namespace radview::test
