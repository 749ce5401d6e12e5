#include "solve/interpolation_error.h"

#include "core/display_transform.h"
#include "core/parallel_for.h"
#include "interp/interpolant.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace radview {

std::vector<double> relativeInterpolationErrors(const RadiosityMesh& valued, double floorY) {
  std::vector<double> errors(valued.elements.size(), 0.0);
  if (valued.elements.empty()) return errors;
  // Gradients fitted to the nodes, not the file's: the estimate is of what the nodal values
  // alone say about the curvature.
  InterpolantOptions options;
  options.useStoredGradients = false;
  const std::unique_ptr<Interpolant> cubic = makeInterpolant(valued, Method::CloughTocher, options);
  parallelFor(
      valued.elements.size(),
      [&](size_t e) {
        const std::vector<uint32_t>& corners = valued.elements[e].corners;
        if (corners.size() < 3) return;
        // The corners' mean is the linear interpolant's value at their mean point (a triangle's
        // centroid, a quad's bilinear centre).
        Vec3 centre(0.0);
        Rgb linear(0.0);
        for (uint32_t node : corners) {
          centre += valued.nodes[node].position;
          linear += valued.nodes[node].B;
        }
        centre /= double(corners.size());
        linear /= double(corners.size());
        const double Ylinear = luminance(linear);
        const double Ycubic = luminance(cubic->evaluate(uint32_t(e), centre).B);
        errors[e] = std::abs(Ycubic - Ylinear) / std::max(Ylinear, floorY);
      },
      256);
  return errors;
}

}  // namespace radview
