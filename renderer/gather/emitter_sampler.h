#pragma once
// Explicit sampling of the emitters for the direct part of the final gather (C&W §9.3.1): the
// direct light carries the sharpest shadows, so it is sampled by area on the emitters rather
// than found by chance through hemisphere directions.
#include "mesh/radiosity_mesh.h"
#include "scene/scene.h"

#include <vector>

namespace radview {

// A point on an emitting element.
struct EmitterSample {
  Vec3 position{0.0};
  Vec3 normal{0.0};  // the emitter's unit normal: it emits on this side only
  Rgb E{0.0};
  // Density of this sample per unit area: an emitter is chosen with probability proportional to
  // its power (area x mean of E's channels), then a point uniformly on it, so pdf = meanE_e /
  // sum over emitters of (A x meanE).
  double pdfArea = 0.0;
  uint32_t element = 0;  // the mesh element it lies on
};

class EmitterSampler {
 public:
  // The mesh's elements whose material emits; zero-area ones are left out (they emit nothing).
  explicit EmitterSampler(const RadiosityMesh& mesh);
  // The same over a scene's polygons (EmitterSample::element then names the polygon).
  explicit EmitterSampler(const Scene& scene);

  bool empty() const { return triangles_.empty(); }
  // Three uniforms in [0, 1): the first picks the emitter (and the triangle of it), the other
  // two the point on that triangle. Precondition: !empty().
  EmitterSample sample(double uPick, double u1, double u2) const;
  // The density per unit area with which sample() draws a point of an emitter of exitance E
  // (EmitterSample::pdfArea), or 0 for a material it never draws: multiple importance sampling
  // weighs a direction that met an emitter by it.
  double pdfArea(const Rgb& E) const;

 private:
  // The emitting ones of `count` polygons, polygonAt(i) giving polygon i's corners and material.
  template <class PolygonAt>
  void build(size_t count, const PolygonAt& polygonAt);

  struct Triangle {
    Vec3 a, b, c, normal;
    Rgb E;
    double pdfArea;
    uint32_t element;
  };
  std::vector<Triangle> triangles_;
  std::vector<double> cumulative_;  // running sum of the triangles' probabilities, the last 1
  double totalPower_ = 0.0;         // sum over the triangles of area x mean of E's channels
};

}  // namespace radview
