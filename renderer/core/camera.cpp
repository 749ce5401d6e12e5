#include "core/camera.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/rotate_vector.hpp>

#include <algorithm>
#include <cmath>

namespace radview {

glm::dmat4 Camera::viewFromWorld() const { return glm::lookAt(eye, target, up); }

glm::dmat4 Camera::clipFromView(double aspect) const { return glm::perspective(yfov, aspect, zNear, zFar); }

void fitClipPlanes(Camera& camera, const Bounds& bounds) {
  const double radius = std::max(0.5 * bounds.diagonal(), 1e-6);
  const double distance = glm::length(bounds.center() - camera.eye);
  camera.zFar = distance + radius * 1.01;
  camera.zNear = std::max(distance - radius * 1.01, camera.zFar * 1e-4);
}

Camera framedFor(const Camera& camera, double aspect) {
  Camera framed = camera;
  if (aspect > 0.0 && aspect < 1.0) framed.yfov = 2.0 * std::atan(std::tan(0.5 * camera.yfov) / aspect);
  return framed;
}

void orbit(Camera& camera, double yawRadians, double pitchRadians) {
  Vec3 offset = camera.eye - camera.target;
  const Vec3 up = glm::normalize(camera.up);
  offset = glm::rotate(offset, -yawRadians, up);
  const Vec3 right = glm::normalize(glm::cross(-offset, up));
  // Keep away from the poles, where the up vector and the view direction would align.
  const double pitchNow = std::asin(glm::clamp(glm::dot(glm::normalize(offset), up), -1.0, 1.0));
  const double limit = glm::radians(89.0);
  const double pitch = glm::clamp(pitchNow + pitchRadians, -limit, limit) - pitchNow;
  offset = glm::rotate(offset, pitch, right);
  camera.eye = camera.target + offset;
}

void pan(Camera& camera, double dxFraction, double dyFraction) {
  const Vec3 forward = camera.forward();
  const Vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const Vec3 up = glm::cross(right, forward);
  const double height = 2.0 * glm::length(camera.target - camera.eye) * std::tan(0.5 * camera.yfov);
  const Vec3 shift = (-dxFraction * right + dyFraction * up) * height;
  camera.eye += shift;
  camera.target += shift;
}

void zoom(Camera& camera, double factor) {
  camera.eye = camera.target + (camera.eye - camera.target) * std::max(factor, 1e-6);
}

void roll(Camera& camera, double radians) {
  // Turning the camera counter-clockwise about its view axis turns the image clockwise.
  camera.up = glm::rotate(camera.up, -radians, camera.forward());
}

}  // namespace radview
