#include "geom/polygon.h"

#include <glm/gtc/constants.hpp>

#include "core/error.h"
#include "geom/triangulate_cgal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace radview {

namespace {

Vec3 vertexMean(const std::vector<Vec3>& vertices) {
  Vec3 sum(0.0);
  for (const Vec3& p : vertices) sum += p;
  return vertices.empty() ? sum : sum / double(vertices.size());
}

double boundingDiagonal(const std::vector<Vec3>& vertices) {
  Bounds b;
  for (const Vec3& p : vertices) b.extend(p);
  return b.diagonal();
}

bool allFinite(const std::vector<Vec3>& vertices) {
  return std::all_of(vertices.begin(), vertices.end(), [](const Vec3& p) { return isFinite(p); });
}

// Sine of the smallest turn, relative to the normal, or -inf when the polygon is not convex:
// a turn against the normal, a fold-back (a collinear corner that reverses), a repeated
// vertex, or a boundary that winds more than once (a star: every turn positive, total 4 pi).
double minTurnSineIfConvex(const std::vector<Vec3>& vertices) {
  const double notConvex = -std::numeric_limits<double>::infinity();
  const Vec3 n = unitNormal(vertices);
  if (n == Vec3(0.0)) return notConvex;
  const size_t count = vertices.size();
  double minSine = std::numeric_limits<double>::infinity();
  double totalTurn = 0.0;
  for (size_t i = 0; i < count; ++i) {
    const Vec3 in = vertices[i] - vertices[(i + count - 1) % count];
    const Vec3 out = vertices[(i + 1) % count] - vertices[i];
    const double lengths = glm::length(in) * glm::length(out);
    if (lengths == 0.0) return notConvex;
    const double sine = glm::dot(glm::cross(in, out), n) / lengths;
    const double cosine = glm::dot(in, out) / lengths;
    if (sine < -1e-9 || (sine <= 1e-9 && cosine < 0.0)) return notConvex;
    minSine = std::min(minSine, sine);
    totalTurn += std::atan2(sine, cosine);
  }
  return totalTurn < 3.0 * glm::pi<double>() ? minSine : notConvex;  // a simple convex boundary turns 2 pi
}

}  // namespace

// Newell's method as the sum of cross products of consecutive vertices, taken about the vertex
// mean: the same vector, but without the cancellation that coordinates far from the origin give.
Vec3 newellNormal(const std::vector<Vec3>& vertices) {
  const Vec3 origin = vertexMean(vertices);
  Vec3 sum(0.0);
  for (size_t i = 0; i < vertices.size(); ++i)
    sum += glm::cross(vertices[i] - origin, vertices[(i + 1) % vertices.size()] - origin);
  return sum;
}

// Degenerate when twice the area is below double rounding of the polygon's size squared.
Vec3 unitNormal(const std::vector<Vec3>& vertices) {
  const Vec3 N = newellNormal(vertices);
  const double length = glm::length(N);
  const double diagonal = boundingDiagonal(vertices);
  if (!(length > 1e-14 * diagonal * diagonal)) return Vec3(0.0);
  return N / length;
}

double area(const std::vector<Vec3>& vertices) { return 0.5 * glm::length(newellNormal(vertices)); }

// Fan of signed triangle areas (signed along the normal, so concave polygons work too).
Vec3 centroid(const std::vector<Vec3>& vertices) {
  const Vec3 n = unitNormal(vertices);
  if (n == Vec3(0.0)) return vertexMean(vertices);
  const Vec3& origin = vertices[0];
  Vec3 weighted(0.0);
  double total = 0.0;
  for (size_t i = 1; i + 1 < vertices.size(); ++i) {
    const double w = glm::dot(glm::cross(vertices[i] - origin, vertices[i + 1] - origin), n);
    weighted += w * (origin + vertices[i] + vertices[i + 1]) / 3.0;
    total += w;
  }
  return weighted / total;
}

double planarityError(const std::vector<Vec3>& vertices) {
  const Vec3 n = unitNormal(vertices);
  const Vec3 mean = vertexMean(vertices);
  double worst = 0.0;
  for (const Vec3& p : vertices) worst = std::max(worst, std::abs(glm::dot(p - mean, n)));
  return worst;
}

bool isConvex(const std::vector<Vec3>& vertices) { return minTurnSineIfConvex(vertices) >= -1e-9; }

bool isStrictlyConvex(const std::vector<Vec3>& vertices, double minSine) {
  return minTurnSineIfConvex(vertices) > minSine;
}

std::vector<std::array<int, 3>> triangulatePolygon(const std::vector<Vec3>& vertices) {
  const int count = static_cast<int>(vertices.size());
  if (count < 3) throw Error("polygon has " + std::to_string(count) + " vertices (at least 3 needed)");
  if (!allFinite(vertices)) throw Error("polygon has a non-finite vertex");
  if (unitNormal(vertices) == Vec3(0.0)) throw Error("polygon is degenerate (zero area)");

  std::vector<std::array<int, 3>> triangles;
  if (isStrictlyConvex(vertices)) {
    for (int i = 1; i + 1 < count; ++i) triangles.push_back({0, i, i + 1});
    return triangles;
  }
  // Projected onto its plane, the polygon is CCW (the frame's n is its normal), and CGAL's
  // faces are CCW in 2D: the triangles keep the polygon's orientation.
  const PlaneFrame frame = planeFrame(vertices);
  std::vector<Vec2> projected;
  projected.reserve(vertices.size());
  for (const Vec3& p : vertices) projected.push_back(frame.project(p));
  return constrainedDelaunayTriangulation(projected);
}

PlaneFrame planeFrame(const std::vector<Vec3>& vertices) {
  PlaneFrame frame;
  frame.n = unitNormal(vertices);
  if (frame.n == Vec3(0.0)) throw Error("polygon is degenerate (zero area): it has no plane");
  frame.origin = vertices[0];
  Vec3 longest(0.0);
  for (size_t i = 0; i < vertices.size(); ++i) {
    const Vec3 edge = vertices[(i + 1) % vertices.size()] - vertices[i];
    if (glm::dot(edge, edge) > glm::dot(longest, longest)) longest = edge;
  }
  frame.u = glm::normalize(longest - glm::dot(longest, frame.n) * frame.n);
  frame.v = glm::cross(frame.n, frame.u);
  return frame;
}

void clipToHalfSpace(const std::vector<Vec3>& polygon, const Vec3& point, const Vec3& m, std::vector<Vec3>& kept) {
  kept.clear();
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Vec3& P = polygon[i];
    const Vec3& Q = polygon[(i + 1) % polygon.size()];
    const double dP = glm::dot(m, P - point), dQ = glm::dot(m, Q - point);
    if (dP >= 0.0) kept.push_back(P);
    // dP - dQ is nonzero when exactly one of them is negative: the crossing lies on the edge.
    if ((dP >= 0.0) != (dQ >= 0.0)) kept.push_back(P + (dP / (dP - dQ)) * (Q - P));
  }
}

}  // namespace radview
