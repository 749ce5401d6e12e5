#include "trace/camera_rays.h"

namespace radview {

CameraRays::CameraRays(const Camera& camera, int width, int height)
    : worldFromClip_(glm::inverse(camera.clipFromWorld(double(width) / double(height)))),
      eye_(camera.eye),
      width_(width),
      height_(height) {}

Ray CameraRays::through(double px, double py) const {
  // The inverse of the rasteriser's viewport map: window x = (ndc.x + 1) / 2 * width, window y
  // (up from the bottom row) = (ndc.y + 1) / 2 * height, and our rows run down.
  const double ndcX = 2.0 * px / width_ - 1.0;
  const double ndcY = 1.0 - 2.0 * py / height_;
  // Unprojecting a point of the far plane through the GL projection itself, not a camera
  // model of our own, keeps the two in step whatever the projection does.
  const glm::dvec4 far = worldFromClip_ * glm::dvec4(ndcX, ndcY, 1.0, 1.0);
  return {eye_, glm::normalize(Vec3(far) / far.w - eye_)};
}

}  // namespace radview
