// Continuity across element edges, as the mesh tags them (the requirement 3; C&W
// §9.2.2 and Salesin, Lischinski, DeRose 1992): the C1 methods are C1 across every untagged
// interior edge, C0 across C0 edges (a kink passes), and across C-1 edges each side is built
// from its own nodes alone. Each check evaluates B and its gradient exactly ON the edge from
// each side's element (evaluate(element, x) uses that element's patch), so a jump is the
// one-sided difference itself, not a finite-difference estimate.
//
// Round-off bounds (measured maxima in brackets, over the seeds and meshes below):
//   gradient jump across a C1 edge <= 1000 eps * max|B| * A / h   [80]
//   value jump across a C1 or C0 edge <= 100 eps * max|B| * A      [7]
// max|B| over the two elements' nodes; A the largest aspect ratio and h the smallest height
// (elementAspect, elementHeight) among the elements around the edge's two elements'
// vertices: on a sliver, and next to one, barycentric coordinates are good to ~eps * A, and
// Powell-Sabin's split points next to a sliver put thin pieces into its neighbours too.
// Relative to the data's largest gradient that is <= 4e-13 on the jittered meshes and <= 2e-7
// on the sliver meshes (aspect up to 1e4), with exact or estimated gradients. Linear,
// bilinear and quadratic jump by more than 1e6 times that bound on the same meshes (measured:
// 1e10 and more).
#include "interp/interpolant.h"
#include "tests/interp/test_meshes.h"

#include <gtest/gtest.h>

namespace radview {
namespace {

using namespace test;

const Plane plane;
constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double kGradientBound = 1000.0, kValueBound = 100.0;
const double kAlong[] = {0.0, 0.1, 0.37, 0.5, 0.81, 1.0};  // points along each edge

Rgb smooth(const Vec2& p) {
  return Rgb(std::sin(3 * p.x) * std::cos(2 * p.y) + 2, std::exp(p.x - p.y), 1 + p.x * p.x * p.y);
}
std::array<Vec2, 3> smoothGradient(const Vec2& p) {
  return {Vec2(3 * std::cos(3 * p.x) * std::cos(2 * p.y), -2 * std::sin(3 * p.x) * std::sin(2 * p.y)),
          Vec2(std::exp(p.x - p.y), -std::exp(p.x - p.y)), Vec2(2 * p.x * p.y, p.x * p.x)};
}

// The largest jumps over the points of an edge, each in units of its round-off bound (normal:
// absolute), and where the last worst one was, for the failure message.
struct Jump {
  double value = 0.0, gradient = 0.0, tangential = 0.0, normal = 0.0;
  double relative = 0.0;  // |gradient jump| / the data's largest gradient
  Vec3 x{0.0};
  InteriorEdge edge;
  std::string where(const RadiosityMesh& mesh) const {
    return "at " + str(x) + " between " + describe(mesh, edge.first) + "\n  and " + describe(mesh, edge.second);
  }
};

class EdgeChecker {
 public:
  EdgeChecker(const RadiosityMesh& mesh, const MethodCase& m)
      : mesh_(mesh), interpolant_(makeInterpolant(mesh, m.method, m.options)), around_(neighbourhoods(mesh)) {
    // The gradient scale: the largest stored (exact, where set) gradient.
    for (const Node& n : mesh.nodes)
      for (const Vec3& g : n.gradient) gradientScale_ = std::max(gradientScale_, glm::length(g));
  }

  // The largest jumps over the given points of the edge.
  Jump across(const InteriorEdge& edge) const {
    const double A = std::max(around_[edge.first].aspect, around_[edge.second].aspect);
    const double h = std::min(around_[edge.first].height, around_[edge.second].height);
    const double B = maxAbsB(mesh_, {edge.first, edge.second});
    const double valueUnit = eps * B * A, gradientUnit = eps * B * A / h;
    const Vec3 t = glm::normalize(edge.b - edge.a);
    const Vec3 n = glm::normalize(glm::cross(mesh_.elementNormal(edge.first), t));
    Jump out;
    out.edge = edge;
    for (double s : kAlong) {
      const Vec3 x = edge.a + s * (edge.b - edge.a);
      const Sample one = interpolant_->evaluate(edge.first, x), two = interpolant_->evaluate(edge.second, x);
      auto worse = [&](double& into, double value) {
        if (value > into) {
          into = value;
          out.x = x;
        }
      };
      for (int c = 0; c < 3; ++c) {
        const Vec3 d = one.gradient[c] - two.gradient[c];
        worse(out.value, std::abs(one.B[c] - two.B[c]) / valueUnit);
        worse(out.gradient, glm::length(d) / gradientUnit);
        worse(out.tangential, std::abs(glm::dot(d, t)) / gradientUnit);
        out.normal = std::max(out.normal, std::abs(glm::dot(d, n)));
        out.relative = std::max(out.relative, glm::length(d) / gradientScale_);
      }
    }
    return out;
  }

  const Interpolant& interpolant() const { return *interpolant_; }

 private:
  const RadiosityMesh& mesh_;
  std::unique_ptr<Interpolant> interpolant_;
  std::vector<Neighbourhood> around_;
  double gradientScale_ = 1e-300;
};

// Seeded random meshes: jittered triangles, triangles with slivers up to aspect 1e4, quads
// (their element edges; the diagonal inside a quad is not an element edge), quadratic
// triangles (gradients from fig. 9.10's parabolas).
std::vector<std::pair<std::string, RadiosityMesh>> continuityMeshes(uint32_t seed) {
  const int n = 5 + int(seed % 4);
  std::vector<std::pair<std::string, RadiosityMesh>> out = {
      {"triangles", gridMesh(n, false, 0.3, smooth, seed, plane)},
      {"slivers", sliverMesh(n, 1e4, 0.4, smooth, seed, plane)},
      {"quads", gridMesh(n, true, 0.3, smooth, seed, plane)},
      {"quadratic triangles", withMidEdgeNodes(gridMesh(n, false, 0.3, smooth, seed, plane), smooth, plane)}};
  for (auto& [name, mesh] : out) setGradients(mesh, smoothGradient, plane);
  return out;
}

TEST(C1Mesh, C1MethodsAreC1AcrossEveryUntaggedInteriorEdge) {
  Jump worst;
  std::map<std::string, double> relative;  // per mesh kind
  for (uint32_t seed = 1; seed <= 10; ++seed)
    for (auto& [name, mesh] : continuityMeshes(seed))
      for (bool stored : {true, false}) {
        mesh.hasGradients = stored;
        for (const MethodCase& m : c1Methods(true)) {
          const EdgeChecker checker(mesh, m);
          for (const InteriorEdge& edge : interiorEdges(mesh)) {
            const Jump jump = checker.across(edge);
            ASSERT_LE(jump.gradient, kGradientBound)
                << "seed " << seed << ", " << name << ", " << m.name << (stored ? ", exact" : ", estimated")
                << " gradients, " << jump.where(mesh);
            ASSERT_LE(jump.value, kValueBound)
                << "seed " << seed << ", " << name << ", " << m.name << (stored ? ", exact" : ", estimated")
                << " gradients, " << jump.where(mesh);
            worst.gradient = std::max(worst.gradient, jump.gradient);
            worst.value = std::max(worst.value, jump.value);
            relative[name] = std::max(relative[name], jump.relative);
          }
        }
      }
  std::printf("[ figures  ] C1 across untagged edges: gradient jump <= %.3g eps B A / h, value jump <= %.3g eps B A\n",
              worst.gradient, worst.value);
  for (const auto& [name, r] : relative)
    std::printf("[ figures  ] C1 across untagged edges, %-20s gradient jump / largest gradient <= %.2g\n", name.c_str(),
                r);
}

TEST(C1Mesh, LinearBilinearAndQuadraticAreOnlyC0) {
  // The same meshes and edges: values agree, gradients jump by far more than the bound
  // above, so the C1 test discriminates.
  double smallest = 1e300;
  for (uint32_t seed = 1; seed <= 3; ++seed)
    for (auto& [name, mesh] : continuityMeshes(seed))
      for (const MethodCase& m : allMethods(true)) {
        if (m.method == Method::C1Quadratic || m.method == Method::CloughTocher) continue;
        const EdgeChecker checker(mesh, m);
        double largest = 0.0;
        for (const InteriorEdge& edge : interiorEdges(mesh)) {
          const Jump jump = checker.across(edge);
          ASSERT_LE(jump.value, kValueBound)
              << "seed " << seed << ", " << name << ", " << m.name << ", " << jump.where(mesh);
          largest = std::max(largest, jump.gradient);
        }
        EXPECT_GT(largest, 1e6 * kGradientBound) << "seed " << seed << ", " << name << ", " << m.name << " is C1?";
        smallest = std::min(smallest, largest / kGradientBound);
      }
  std::printf("[ figures  ] linear, bilinear, quadratic: largest gradient jump >= %.2g times the C1 bound\n", smallest);
}

// An 8 x 8 jittered grid whose column x = 0.5 and row y = 0.5 are straight, with the L of
// edges {x = 0.5, y <= 0.5} and {y = 0.5, x >= 0.5} tagged C0, and data with a kink there:
// smooth + k (x - 1/2)+ (1/2 - y)+, whose normal derivative jumps by k (1/2 - y) across the
// vertical leg and by k (x - 1/2) across the horizontal one, and which is C1 at the corner
// of the L (0.5, 0.5): the apex of two non-collinear C0 boundaries (Salesin et al.).
constexpr double kKink = 4.0;
Rgb kinked(const Vec2& p) {
  return smooth(p) + Rgb(kKink, -kKink, 0.5 * kKink) * std::max(0.0, p.x - 0.5) * std::max(0.0, 0.5 - p.y);
}
bool onL(const Vec2& a, const Vec2& b) {
  auto near = [](double u, double v) { return std::abs(u - v) < 1e-9; };
  const bool vertical = near(a.x, 0.5) && near(b.x, 0.5) && a.y <= 0.5 + 1e-9 && b.y <= 0.5 + 1e-9;
  const bool horizontal = near(a.y, 0.5) && near(b.y, 0.5) && a.x >= 0.5 - 1e-9 && b.x >= 0.5 - 1e-9;
  return vertical || horizontal;
}
RadiosityMesh kinkMesh(uint32_t seed, bool tagged) {
  RadiosityMesh mesh = gridMesh(8, false, 0.3, kinked, seed, plane);
  straightenGridLines(mesh, 8, 4, 4, plane);
  setValues(mesh, kinked, plane);
  if (tagged) tagEdges(mesh, onL, Continuity::C0, plane);
  return mesh;
}

TEST(C1Mesh, C0EdgesKeepValueAndTangentialDerivativeAndLetTheKinkThrough) {
  double smallestKinkRatio = 1e300;
  for (uint32_t seed = 1; seed <= 4; ++seed) {
    const RadiosityMesh mesh = kinkMesh(seed, true);
    ASSERT_EQ(MeshTopology(mesh).countEdges(Continuity::C0), 8u);
    for (const MethodCase& m : allMethods(false)) {
      const EdgeChecker checker(mesh, m);
      const bool c1 = m.method == Method::C1Quadratic || m.method == Method::CloughTocher;
      for (const InteriorEdge& edge : interiorEdges(mesh)) {
        const Jump jump = checker.across(edge);
        auto input = [&] { return "seed " + std::to_string(seed) + ", " + m.name + ", " + jump.where(mesh); };
        ASSERT_LE(jump.value, kValueBound) << input();
        if (!c1) continue;
        if (edge.continuity == Continuity::C1) {
          ASSERT_LE(jump.gradient, kGradientBound) << input();
          continue;
        }
        // Per-side gradients agree along the edge (Salesin's adjustment), so B along it is one
        // curve seen from both sides...
        ASSERT_LE(jump.tangential, kGradientBound) << input();
        // ...while the derivative across it jumps about as the data's does (at the edge's
        // midpoint: the exact jump is k times the distance from the L's corner along the leg).
        const Vec2 mid = plane.coords(0.5 * (edge.a + edge.b));
        const double exact = kKink * (std::abs(mid.x - 0.5) + std::abs(mid.y - 0.5));
        smallestKinkRatio = std::min(smallestKinkRatio, jump.normal / exact);
        EXPECT_GT(jump.normal, 0.3 * exact) << input();
      }
      // At the corner of the L every element around it has the same gradient.
      if (c1) {
        const Vec3 corner = plane.at(0.5, 0.5);
        const uint32_t node = 4 * 9 + 4;  // gridMesh numbering: j (n + 1) + i
        ASSERT_LT(glm::length(mesh.nodes[node].position - corner), 1e-15);
        std::vector<Sample> samples;
        for (uint32_t e = 0; e < mesh.elements.size(); ++e)
          for (uint32_t c : mesh.elements[e].corners)
            if (c == node) samples.push_back(checker.interpolant().evaluate(e, corner));
        ASSERT_GE(samples.size(), 4u);
        for (const Sample& s : samples)
          for (int c = 0; c < 3; ++c)
            EXPECT_LT(glm::length(s.gradient[c] - samples[0].gradient[c]), 1e-12 * kKink)
                << "seed " << seed << ", " << m.name << ": the apex of the L is not C1";
      }
    }
  }
  std::printf("[ figures  ] C0 edges: normal-derivative jump / the data's >= %.3g (C1 methods, estimated gradients)\n",
              smallestKinkRatio);
}

TEST(C1Mesh, WithoutTheC0TagsTheKinkIsSmoothedAway) {
  // The control for the test above: the same data, untagged, is interpolated C1 across the L.
  const RadiosityMesh mesh = kinkMesh(1, false);
  for (const MethodCase& m : c1Methods(false)) {
    const EdgeChecker checker(mesh, m);
    for (const InteriorEdge& edge : interiorEdges(mesh))
      ASSERT_LE(checker.across(edge).gradient, kGradientBound) << m.name;
  }
}

// An 8 x 8 grid cut along x = 0.5 (cutAlongLine: nodes on the line duplicated for the right
// side, the line tagged C-1), as triangles, quads or quadratic triangles.
struct CutMesh {
  std::string name;
  RadiosityMesh mesh;
  std::map<uint32_t, uint32_t> twin;
};
std::vector<CutMesh> cutMeshes(uint32_t seed) {
  std::vector<CutMesh> out;
  for (int kind = 0; kind < 3; ++kind) {
    CutMesh cut{kind == 0   ? "triangles"
                : kind == 1 ? "quads"
                            : "quadratic triangles",
                gridMesh(8, kind == 1, 0.3, smooth, seed, plane),
                {}};
    straightenGridLines(cut.mesh, 8, 4, -1, plane);
    if (kind == 2) cut.mesh = withMidEdgeNodes(cut.mesh, smooth, plane);
    cut.twin = cutAlongLine(cut.mesh, 0.5, plane);
    out.push_back(std::move(cut));
  }
  return out;
}
bool rightSide(const RadiosityMesh& mesh, uint32_t node, const std::map<uint32_t, uint32_t>& twin) {
  const double x = plane.coords(mesh.nodes[node].position).x;
  if (std::abs(x - 0.5) >= 1e-9) return x > 0.5;
  for (const auto& [left, right] : twin)
    if (right == node) return true;
  return false;
}
bool rightElement(const RadiosityMesh& mesh, uint32_t element, const std::map<uint32_t, uint32_t>& twin) {
  for (uint32_t c : mesh.elements[element].corners)
    if (rightSide(mesh, c, twin)) return true;
  return false;
}

TEST(C1Mesh, AcrossCMinus1EdgesEachSideDependsOnlyOnItsOwnNodes) {
  for (uint32_t seed = 1; seed <= 3; ++seed)
    for (CutMesh& cut : cutMeshes(seed)) {
      RadiosityMesh& mesh = cut.mesh;
      ASSERT_GT(MeshTopology(mesh).countEdges(Continuity::Cm1), 7u);
      setGradients(mesh, smoothGradient, plane);
      // The other side's data, changed: values and stored gradients.
      RadiosityMesh changed = mesh;
      std::mt19937 random(seed);
      std::uniform_real_distribution<double> any(-5.0, 5.0);
      for (uint32_t n = 0; n < changed.nodes.size(); ++n)
        if (rightSide(changed, n, cut.twin)) {
          changed.nodes[n].B = Rgb(any(random), any(random), any(random));
          for (Vec3& g : changed.nodes[n].gradient) g = worldGradient(Vec2(any(random), any(random)), plane);
        }
      for (bool stored : {true, false}) {
        mesh.hasGradients = changed.hasGradients = stored;
        for (const MethodCase& m : allMethods(true)) {
          const auto before = makeInterpolant(mesh, m.method, m.options);
          const auto after = makeInterpolant(changed, m.method, m.options);
          std::mt19937 points(seed);
          for (uint32_t e = 0; e < mesh.elements.size(); ++e) {
            if (rightElement(mesh, e, cut.twin)) continue;
            std::vector<Vec3> xs;
            for (uint32_t c : mesh.elements[e].corners) xs.push_back(mesh.nodes[c].position);  // on the line too
            for (int k = 0; k < 6; ++k) xs.push_back(randomPointIn(mesh, e, points));
            for (const Vec3& x : xs) {
              const Sample s0 = before->evaluate(e, x), s1 = after->evaluate(e, x);
              ASSERT_EQ(s0.B, s1.B) << "seed " << seed << ", " << cut.name << ", " << m.name
                                    << (stored ? ", exact" : ", estimated") << " gradients: the left side moved at "
                                    << str(x) << " in " << describe(mesh, e);
              for (int c = 0; c < 3; ++c) ASSERT_EQ(s0.gradient[c], s1.gradient[c]);
            }
          }
        }
      }
    }
}

TEST(C1Mesh, AcrossCMinus1EdgesTheValuesDifferByTheStep) {
  // Linear data on each side, a step of (2, -1, 0.5) between them: every method reproduces
  // each side's linear data, so on the edge the two sides differ by the step exactly.
  const Rgb step(2.0, -1.0, 0.5);
  const Field left = [](const Vec2& p) { return Rgb(1 + p.x + 2 * p.y, 3 - p.x, 2 + p.y); };
  for (CutMesh& cut : cutMeshes(4)) {
    RadiosityMesh& mesh = cut.mesh;
    for (uint32_t n = 0; n < mesh.nodes.size(); ++n)
      mesh.nodes[n].B = left(plane.coords(mesh.nodes[n].position)) + (rightSide(mesh, n, cut.twin) ? step : Rgb(0.0));
    for (const MethodCase& m : allMethods(false)) {
      const EdgeChecker checker(mesh, m);
      for (const InteriorEdge& edge : interiorEdges(mesh)) {
        if (edge.continuity != Continuity::Cm1) continue;
        for (double s : kAlong) {
          const Vec3 x = edge.a + s * (edge.b - edge.a);
          const bool firstIsRight = rightElement(mesh, edge.first, cut.twin);
          const Rgb jump = checker.interpolant().evaluate(firstIsRight ? edge.first : edge.second, x).B -
                           checker.interpolant().evaluate(firstIsRight ? edge.second : edge.first, x).B;
          EXPECT_LT(glm::length(jump - step), 1e-13) << cut.name << ", " << m.name << " at " << str(x);
        }
      }
    }
  }
}

}  // namespace
}  // namespace radview
