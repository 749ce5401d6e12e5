#pragma once
// The eye rays of the GL renderer's camera, so that a final-gather image lines up with a GL
// render of the same camera and size pixel for pixel.
#include "core/camera.h"
#include "trace/ray_caster.h"

namespace radview {

class CameraRays {
 public:
  // The image is width x height pixels, the aspect ratio width / height, as MeshRenderer::render.
  CameraRays(const Camera& camera, int width, int height);

  // The ray from the eye through the image point (px, py), in pixels from the top-left corner of
  // the image (x right, y down: row 0 is the top row, as in LinearImage). Pixel (i, j) spans
  // [i, i+1] x [j, j+1]; its centre (i + 0.5, j + 0.5) is where the rasteriser samples it.
  Ray through(double px, double py) const;

 private:
  glm::dmat4 worldFromClip_;
  Vec3 eye_;
  double width_, height_;
};

}  // namespace radview
