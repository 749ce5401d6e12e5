#pragma once
// Which element edge the user points at in a view: the eye ray through the pixel finds the
// element (Embree, as the final gather's eye rays do), then the element's nearest edge, if it is
// within a few pixels of the point.
#include "core/camera.h"
#include "edit/continuity_edit.h"
#include "trace/ray_caster.h"

#include <memory>
#include <optional>
#include <vector>

namespace radview {

class EdgePicker {
 public:
  // Builds the ray caster over the mesh's elements (element i is polygon i). The mesh's
  // positions are copied: the picker stays valid through edits that change only nodes' sharing.
  explicit EdgePicker(const RadiosityMesh& mesh);

  // The edge nearest to what pixel point (px, py) sees (pixels from the top left, as
  // CameraRays), if within `tolerancePixels` of it there; nullopt over the background or far
  // from every edge.
  std::optional<EdgeRef> pick(const Camera& camera, int width, int height, double px, double py,
                              double tolerancePixels = 6.0) const;

  // Every edge a stroke through these pixel points passes near, in stroke order, each once.
  std::vector<EdgeRef> pickAlong(const Camera& camera, int width, int height,
                                 const std::vector<std::pair<double, double>>& points,
                                 double tolerancePixels = 6.0) const;

 private:
  std::vector<std::vector<Vec3>> corners_;  // per element, its corner positions
  std::unique_ptr<RayCaster> caster_;
};

}  // namespace radview
