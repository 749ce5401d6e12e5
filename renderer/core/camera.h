#pragma once
// A pinhole camera, framed for a view and moved by the mouse.
#include "core/types.h"

namespace radview {

struct Camera {
  Vec3 eye{0.0, 0.0, 1.0};
  Vec3 target{0.0};
  Vec3 up{0.0, 1.0, 0.0};
  double yfov = glm::radians(45.0);  // full vertical field of view
  double zNear = 0.01, zFar = 100.0;

  glm::dmat4 viewFromWorld() const;
  glm::dmat4 clipFromView(double aspect) const;
  glm::dmat4 clipFromWorld(double aspect) const { return clipFromView(aspect) * viewFromWorld(); }
  Vec3 forward() const { return glm::normalize(target - eye); }
};

// The camera as a view of this aspect ratio (width / height) shows it: the same, or, for a
// view narrower than it is tall, a wider vertical field, so that the view covers the camera's
// vertical field across its width too and what a camera was fitted to stays in view whatever
// the window's shape.
Camera framedFor(const Camera& camera, double aspect);

// Sets zNear/zFar to enclose `bounds` as seen from the camera, with a near plane no closer
// than 1e-4 of the far one (depth precision).
void fitClipPlanes(Camera& camera, const Bounds& bounds);

// Orbit / pan / zoom about the target, and roll about the view axis (fig. 9.8 rotates the
// view in 45-degree steps).
void orbit(Camera& camera, double yawRadians, double pitchRadians);
void pan(Camera& camera, double dxFraction, double dyFraction);  // fractions of the view height
void zoom(Camera& camera, double factor);                        // distance to target *= factor
void roll(Camera& camera, double radians);                       // clockwise on screen for > 0

}  // namespace radview
