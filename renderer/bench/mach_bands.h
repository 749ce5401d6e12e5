#pragma once
// A Mach-band measure (C&W §9.2.2): the eye sees a jump in the gradient of displayed
// luminance as a band, and linear interpolation puts one at every element edge, where the
// radiosity function itself is smooth. The measure is the mean jump of the image gradient
// across element edges, taken on four-pixel stencils p0 p1 | p2 p3 along a row or column that
// cross exactly one edge between p1 and p2:
//     jump = (L(p3) - L(p2)) - (L(p1) - L(p0)),   L the displayed luminance in 8-bit steps,
// so a method whose gradient is continuous scores about the image's own curvature, and one
// with Mach bands scores more. Edges tagged C0 in the mesh are measured apart: there the
// radiosity has a real kink, which a good method keeps (Salesin et al. 1992; fig. 9.14).
#include "core/image.h"
#include "mesh/radiosity_mesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace radview {

struct EdgeStencils {
  std::vector<std::array<uint32_t, 4>> smooth;  // across untagged element edges: no kink in B
  std::vector<std::array<uint32_t, 4>> c0;      // across edges tagged C0: a real kink
};

// The stencils of a view, from the element seen at each pixel (visibleElements): p0, p1 on one
// element, p2, p3 on a neighbour in the same plane that shares a whole edge with it; emitters
// and edges tagged C-1 (a jump in value, not in gradient) are left out.
EdgeStencils edgeStencils(const RadiosityMesh& mesh, const std::vector<int32_t>& elementAt, int width, int height);

// The mean |jump| over the stencils (8-bit steps per pixel), of `image` shown at exposureScale
// (exposure, clamp, sRGB: display_transform.h). Stencils with an uncovered or non-finite pixel
// are skipped; 0 when none is left.
double meanGradientJump(const LinearImage& image, double exposureScale,
                        const std::vector<std::array<uint32_t, 4>>& stencils);

}  // namespace radview
