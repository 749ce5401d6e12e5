#pragma once
// Per-pixel comparison of a GPU rendering of a planar mesh with the CPU reference
// interpolant: every covered pixel centre is traced to its point on the mesh's plane and
// evaluated on the CPU.
#include "core/camera.h"
#include "core/image.h"
#include "geom/polygon.h"
#include "interp/interpolant.h"
#include "interp/surface_locator.h"

#include <cmath>
#include <iostream>

namespace radview::test {

struct PixelComparison {
  size_t pixels = 0, withinTolerance = 0;
  double maxError = 0.0;
};

inline PixelComparison compareWithReference(const LinearImage& image, const Camera& camera, const RadiosityMesh& mesh,
                                            const Interpolant& reference, double tolerance) {
  const Vec3 n = mesh.elementNormal(0);
  const Vec3 origin = mesh.nodes[mesh.elements[0].corners[0]].position;
  const glm::dmat4 worldFromClip = glm::inverse(camera.clipFromWorld(double(image.width) / image.height));
  const SurfaceLocator locator(mesh);
  PixelComparison result;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float* p = &image.rgba[(size_t(y) * image.width + x) * 4];
      if (p[3] == 0.0f) continue;
      const double nx = (x + 0.5) / image.width * 2 - 1, ny = 1 - (y + 0.5) / image.height * 2;
      const glm::dvec4 a = worldFromClip * glm::dvec4(nx, ny, -1, 1), b = worldFromClip * glm::dvec4(nx, ny, 1, 1);
      const Vec3 from = Vec3(a) / a.w, direction = Vec3(b) / b.w - from;
      const Vec3 hit = from + direction * (glm::dot(origin - from, n) / glm::dot(direction, n));
      const SurfacePoint point = locator.nearest(hit);
      const Rgb want = reference.evaluate(point.element, point.x).B;
      double error = 0.0;
      for (int c = 0; c < 3; ++c) {
        const double e = std::abs(double(p[c]) - want[c]);
        error = std::isnan(e) ? INFINITY : std::max(error, e);  // a NaN pixel must fail
      }
      ++result.pixels;
      if (error <= tolerance) ++result.withinTolerance;
      result.maxError = std::max(result.maxError, error);
    }
  std::cout << result.pixels << " pixels, " << result.withinTolerance << " within " << tolerance
            << " of the CPU reference, max difference " << result.maxError << "\n";
  return result;
}

// `mesh` with `count` small triangles behind `camera`, parallel to z = 0, out of every pixel's
// view: enough of them give a draw more vertices than the image has pixels, which switches
// the renderer's paths that read per vertex to reading per pixel (MeshRenderer::drawPolygons,
// DeferredPass::draw).
inline RadiosityMesh withTrianglesBehind(RadiosityMesh mesh, const Camera& camera, int count) {
  const Vec3 behind = camera.eye + 2.0 * (camera.eye - camera.target);
  for (int i = 0; i < count; ++i) {
    const uint32_t first = uint32_t(mesh.nodes.size());
    for (const Vec3& d : {Vec3(0, 0, 0), Vec3(0.01, 0, 0), Vec3(0, 0.01, 0)})
      mesh.nodes.push_back({behind + d + Vec3(0, 0, 0.001 * i), Rgb(0.5), {}});
    mesh.elements.push_back(Element{{first, first + 1, first + 2}, {}, 0, 0});
  }
  return mesh;
}

}  // namespace radview::test
