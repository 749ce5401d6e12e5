// Extreme inputs (the requirement 5): slivers up to aspect ratio 1e7 (needles: one
// short edge; caps: one vertex near the opposite edge), radiosities from 1e-8 to 1e8 in one
// mesh, nearly collinear gradient stencils, zero-area triangles and non-convex quads. Every
// method stays finite and its error within the documented round-off (eps * aspect of the
// data's scale); the figures renderer/interp/README.md quotes are printed as "[ figures ]" lines.
//
// Limits of the mesh layer met on the way (MeshTopology, renderer/mesh/topology.cpp):
//  - nodes closer than 1e-7 of the mesh's diagonal share one position, so a needle whose
//    short edge is below that (aspect 1e7 in a mesh as long as the needle) is welded: its
//    long edges then match no single neighbour, and it is interpolated on its own (no C1
//    across it); values stay finite.
//  - a node within 1e-5 (of the edge's length) of an edge is taken for a T-vertex of the
//    elements along that edge, and the apex of a cap of aspect > 1e5 is such a node for the
//    element across the cap's long edge; SurfaceTriangulation now ignores a "T-vertex" that
//    the element across the same edge has as a corner (MeshTopology still counts it).
#include "core/error.h"
#include "interp/interpolant.h"
#include "tests/interp/test_meshes.h"

#include <gtest/gtest.h>

namespace radview {
namespace {

using namespace test;

const Plane plane;
constexpr double eps = std::numeric_limits<double>::epsilon();

const Rgb kLinearAt0(1.0, 2.0, 1.0);
const Vec2 kLinearSlope[3] = {{1.0, 0.5}, {-1.0, 0.0}, {0.25, 3.0}};
Rgb linear(const Vec2& p) {
  Rgb out = kLinearAt0;
  for (int c = 0; c < 3; ++c) out[c] += glm::dot(kLinearSlope[c], p);
  return out;
}
std::array<Vec2, 3> linearGradient(const Vec2&) { return {kLinearSlope[0], kLinearSlope[1], kLinearSlope[2]}; }

bool finite(const Sample& s) {
  bool ok = isFinite(s.B);
  for (const Vec3& g : s.gradient) ok &= isFinite(g);
  return ok;
}

// A square [0,1]^2 cut into four triangles about a node at (1/2, 1/aspect) just above the
// bottom edge, so the bottom triangle is a cap of that aspect ratio, and one more triangle
// below the cap's long edge (its neighbour across it).
RadiosityMesh capMesh(double aspect, const Field& f) {
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"grey", Rgb(0.5), Rgb(0.0)});
  for (const Vec2& p : {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1), Vec2(0.5, 1.0 / aspect), Vec2(0.5, -0.5)})
    mesh.nodes.push_back({plane.at(p.x, p.y), f(p), {}});
  for (const std::array<uint32_t, 3>& t :
       {std::array<uint32_t, 3>{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 5, 1}})
    mesh.elements.push_back(Element{{t[0], t[1], t[2]}, {}, 0, 0});
  return mesh;
}

// A 4 x 4 grid with a row of needles of aspect ratio `aspect` inserted above y = 1/2: cells
// 1/4 wide and 1/(4 aspect) high, each cut into two needles. The row's upper nodes are
// sheared sideways by about their height, so the needles' short edges are not perpendicular
// to their long ones (a needle with a perpendicular short edge is the affine image of a good
// triangle, and hides the book variant's trouble).
RadiosityMesh needleMesh(double aspect, const Field& f) {
  const int n = 4;
  const double delta = 1.0 / n / aspect;
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"grey", Rgb(0.5), Rgb(0.0)});
  std::vector<double> ys;
  for (int j = 0; j <= n; ++j) {
    ys.push_back(double(j) / n);
    if (2 * j == n) ys.push_back(0.5 + delta);
  }
  for (size_t j = 0; j < ys.size(); ++j)
    for (int i = 0; i <= n; ++i) {
      Vec2 p(double(i) / n, ys[j]);
      if (ys[j] == 0.5 + delta && i > 0 && i < n) p.x += delta * (i % 2 ? 1.0 : -0.7);
      mesh.nodes.push_back({plane.at(p.x, p.y), f(p), {}});
    }
  addGridCells(mesh, n, int(ys.size()) - 1, false, [](int i, int j) { return (i + j) % 2 != 0; });
  return mesh;
}

// Max over random points of every element of |B - linear| and |grad B - grad linear|, in
// units of eps * (largest aspect ratio of the mesh) * max|B| (per unit length, for the
// gradient: the meshes here are about 1 across).
struct LinearErrors {
  double value = 0.0, gradient = 0.0;
  bool finite = true;
};
LinearErrors linearErrors(const RadiosityMesh& mesh, const MethodCase& m) {
  double aspect = 1.0, B = 0.0;
  for (uint32_t e = 0; e < mesh.elements.size(); ++e) {
    aspect = std::max(aspect, elementAspect(mesh, e));
    B = std::max(B, maxAbsB(mesh, {e}));
  }
  const auto interpolant = makeInterpolant(mesh, m.method, m.options);
  std::mt19937 random(2);
  LinearErrors out;
  for (uint32_t e = 0; e < mesh.elements.size(); ++e) {
    std::vector<Vec3> xs;
    for (uint32_t c : mesh.elements[e].corners) xs.push_back(mesh.nodes[c].position);
    for (int k = 0; k < 50; ++k) xs.push_back(randomPointIn(mesh, e, random));
    for (const Vec3& x : xs) {
      const Sample s = interpolant->evaluate(e, x);
      out.finite &= finite(s);
      out.value = std::max(out.value, glm::length(s.B - linear(plane.coords(x))) / (eps * aspect * B));
      for (int c = 0; c < 3; ++c)
        out.gradient = std::max(
            out.gradient, glm::length(s.gradient[c] - worldGradient(kLinearSlope[c], plane)) / (eps * aspect * B));
    }
  }
  return out;
}

TEST(Extremes, CapsAndNeedlesUpToAspect1e7ReproduceLinearDataToRoundOff) {
  // Every method, exact and estimated gradients, linear data. Bounds (measured maxima):
  //  - value error <= 4 eps A max|B|                                   [0.08]
  //  - gradient error, linear, bilinear, quadratic, c1-quadratic:
  //      <= 64 eps A max|B| / L (L = 1, the meshes' size)              [38]
  //  - gradient error, Clough-Tocher: <= 4 eps A^2 max|B| / L: its wedge (the inner control
  //    value c next to each edge) divides by the cross direction's component into the piece,
  //    which on a needle is ~1/A of the direction's length, so c carries ~eps A max|B|, and
  //    the needle is L / A thick                             [affine 0.02, book 0.75]
  // Needles of aspect 1e7 here have short edges (2.5e-8) below MeshTopology's weld distance
  // (1e-7 of the diagonal): welded, their estimated gradients are meaningless and only
  // finiteness is asserted for them (measured: value errors up to 30 with the book variant,
  // 1e-8 with the others). Before the fixes in surface_triangulation.cpp (caps) and
  // vertex_gradients.cpp (the least-squares eigenvector), estimated gradients were off by up
  // to 0.5 on caps of aspect >= 1e5 and by 1e-8 on the regular part of the needle mesh.
  for (double aspect : {1e3, 1e4, 1e5, 1e6, 1e7})
    for (const bool needles : {false, true}) {
      RadiosityMesh mesh = needles ? needleMesh(aspect, linear) : capMesh(aspect, linear);
      setGradients(mesh, linearGradient, plane);
      const bool welded = MeshTopology(mesh).positionCount() < mesh.nodes.size();
      EXPECT_EQ(welded, needles && aspect >= 1e7);
      for (bool stored : {true, false}) {
        mesh.hasGradients = stored;
        for (const MethodCase& m : allMethods(true)) {
          const LinearErrors errors = linearErrors(mesh, m);
          const std::string input = std::string(needles ? "needles" : "cap") + " of aspect " + std::to_string(aspect) +
                                    ", " + m.name + (stored ? ", exact" : ", estimated") + " gradients";
          EXPECT_TRUE(errors.finite) << input;
          if (welded && !stored) continue;
          EXPECT_LE(errors.value, 4.0) << input;
          const double gradientBound = m.method == Method::CloughTocher ? 4.0 * aspect : 64.0;
          EXPECT_LE(errors.gradient, gradientBound) << input;
        }
      }
    }
}

TEST(Extremes, CapsUpToAspect1e7AreC1AcrossTheirEdges) {
  // Smooth data, exact and estimated gradients: the cap joins the triangle below its long
  // edge C1, to round-off. That round-off grows like eps A^2: the cap must bend by the data's
  // O(L^2) variation within its height L / A, so its curvature across is ~A^2 / L^2 times the
  // data's, and the evaluation point's own rounding (~eps L) moves the gradient by that.
  // Asserted: jump <= 4 eps A^2 max|B| / L (measured <= 0.25; 7e-3 absolute at aspect 1e7,
  // on gradients of size ~3). The tangential part is C0's business: <= 64 eps A max|B| / L
  // (measured <= 1).
  const Field f = [](const Vec2& p) { return Rgb(2 + std::sin(3 * p.x) * p.y, std::exp(p.x), 1 + p.x * p.y); };
  const GradientField g = [](const Vec2& p) {
    return std::array<Vec2, 3>{Vec2(3 * std::cos(3 * p.x) * p.y, std::sin(3 * p.x)), Vec2(std::exp(p.x), 0),
                               Vec2(p.y, p.x)};
  };
  for (double aspect : {1e3, 1e4, 1e5, 1e6, 1e7}) {
    RadiosityMesh mesh = capMesh(aspect, f);
    setGradients(mesh, g, plane);
    double B = 0.0;
    for (uint32_t e = 0; e < mesh.elements.size(); ++e) B = std::max(B, maxAbsB(mesh, {e}));
    for (bool stored : {true, false}) {
      mesh.hasGradients = stored;
      for (const MethodCase& m : c1Methods(true)) {
        const auto interpolant = makeInterpolant(mesh, m.method, m.options);
        for (double s : {0.1, 0.3, 0.5, 0.7, 0.9}) {
          const Vec3 x = plane.at(s, 0.0);
          const Sample cap = interpolant->evaluate(0, x), below = interpolant->evaluate(4, x);
          for (int c = 0; c < 3; ++c) {
            const Vec3 jump = cap.gradient[c] - below.gradient[c];
            const std::string input = "cap of aspect " + std::to_string(aspect) + ", " + m.name +
                                      (stored ? ", exact" : ", estimated") + " gradients, at s = " + std::to_string(s);
            EXPECT_LE(glm::length(jump), 4 * eps * aspect * aspect * B) << input;
            EXPECT_LE(std::abs(glm::dot(jump, plane.u)), 64 * eps * aspect * B) << input;
          }
        }
      }
    }
  }
}

// Noise of standard deviation sigma on every nodal value (all channels).
void addNoise(RadiosityMesh& mesh, double sigma, uint32_t seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  for (Node& n : mesh.nodes) n.B += Rgb(noise(random), noise(random), noise(random));
}

TEST(Extremes, TheBookCloughTocherAmplifiesNoiseOnNeedlesTheAffineOneDoesNot) {
  // Linear data + noise (sigma 1e-3) on the needle row; over the needles, the largest |B|
  // relative to the largest nodal |B| of the element ("amplification"), and how far B leaves
  // the element's nodal range, in units of sigma. The book's cross direction (the edge
  // normal) is nearly parallel to a sheared needle's short edge in the needle's affine frame,
  // so its wedge divides the noise by ~1/aspect: the overshoot grows like 0.13 aspect sigma
  // (at 1e7 the row is welded, see above, and the figure is the patches' own). The
  // affine-invariant direction (centroid to centroid) and Powell-Sabin stay in range:
  // AffineInvariant is rightly the default.
  const double sigma = 1e-3;
  for (double aspect : {1e3, 1e4, 1e5, 1e6, 1e7}) {
    RadiosityMesh mesh = needleMesh(aspect, linear);
    addNoise(mesh, sigma, 9);
    setGradients(mesh, linearGradient, plane);
    for (bool stored : {true, false}) {
      mesh.hasGradients = stored;
      for (const MethodCase& m : c1Methods(true)) {
        const auto interpolant = makeInterpolant(mesh, m.method, m.options);
        std::mt19937 random(4);
        double amplification = 0.0, excess = 0.0;
        for (uint32_t e = 0; e < mesh.elements.size(); ++e) {
          if (elementAspect(mesh, e) < aspect / 10) continue;
          Rgb lo(1e300), hi(-1e300);
          for (uint32_t c : mesh.elements[e].corners) {
            lo = glm::min(lo, mesh.nodes[c].B);
            hi = glm::max(hi, mesh.nodes[c].B);
          }
          const double nodal = std::max({std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), hi.x, hi.y, hi.z});
          for (int k = 0; k < 300; ++k) {
            const Rgb B = interpolant->evaluate(e, randomPointIn(mesh, e, random)).B;
            for (int c = 0; c < 3; ++c) {
              amplification = std::max(amplification, std::abs(B[c]) / nodal);
              excess = std::max(excess, std::max(B[c] - hi[c], lo[c] - B[c]) / sigma);
            }
          }
        }
        std::printf(
            "[ figures  ] needles of aspect %.0e, %-9s gradients, %-24s amplification %9.4g, out of range by %9.3g "
            "sigma\n",
            aspect, stored ? "exact" : "estimated", m.name.c_str(), amplification, excess);
        const std::string input = "aspect " + std::to_string(aspect) + ", " + m.name;
        if (m.options.cloughTocher == CloughTocherVariant::Book && m.method == Method::CloughTocher)
          EXPECT_GT(excess, 0.01 * aspect) << input;  // the trouble, pinned: a fix would show here
        else
          EXPECT_LE(excess, 1.0) << input;
      }
    }
  }
  EXPECT_EQ(InterpolantOptions().cloughTocher, CloughTocherVariant::AffineInvariant);
}

TEST(Extremes, HighDynamicRangeDataStaysFiniteAndTheC1MethodsGoNegativeByAMeasuredAmount) {
  // Radiosities from 1e-8 to 1e8 in one 8 x 8 mesh: random per node (log-uniform), and the
  // smooth 10^(16 x - 8) (a factor 100 per cell). Every method stays finite and interpolates
  // the nodes to round-off of the element's largest value; linear and bilinear never go
  // negative (convex combinations). The C1 methods do: next to a node of 1e8 the estimated
  // gradients are huge and the patches of its dim neighbours dip below zero. Measured and
  // printed: min B relative to the largest nodal value around the element (the nodes of all
  // elements sharing a vertex with it), and the share of elements that go negative; asserted
  // no worse than -0.12 of that neighbourhood value.
  for (int kind = 0; kind < 2; ++kind) {
    RadiosityMesh mesh = gridMesh(8, false, 0.3, linear, 31, plane);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> exponent(-8.0, 8.0);
    for (Node& n : mesh.nodes) {
      const Vec2 p = plane.coords(n.position);
      n.B = kind == 0
                ? Rgb(std::pow(10.0, exponent(random)), std::pow(10.0, exponent(random)),
                      std::pow(10.0, exponent(random)))
                : Rgb(std::pow(10.0, 16 * p.x - 8), std::pow(10.0, 8 - 16 * p.y), std::pow(10.0, 16 * p.x * p.y - 8));
    }
    // The largest nodal value per channel around each element.
    const MeshTopology topology(mesh);
    std::vector<Rgb> atPosition(topology.positionCount(), Rgb(0.0));
    for (const Element& e : mesh.elements)
      for (uint32_t c : e.corners)
        for (uint32_t d : e.corners)
          atPosition[topology.positionId(c)] = glm::max(atPosition[topology.positionId(c)], mesh.nodes[d].B);
    for (const MethodCase& m : allMethods(false)) {
      const auto interpolant = makeInterpolant(mesh, m.method, m.options);
      std::mt19937 points(4);
      double worst = 0.0, worstOwn = 0.0, nodeError = 0.0;
      int negative = 0;
      for (uint32_t e = 0; e < mesh.elements.size(); ++e) {
        Rgb around(0.0), own(0.0);
        for (uint32_t c : mesh.elements[e].corners) {
          around = glm::max(around, atPosition[topology.positionId(c)]);
          own = glm::max(own, mesh.nodes[c].B);
        }
        for (uint32_t c : mesh.elements[e].corners) {
          const Sample s = interpolant->evaluate(e, mesh.nodes[c].position);
          // The C1 patches' control values next to a node carry its gradient, estimated from
          // the neighbourhood, so their round-off scales with the neighbourhood's values.
          const Rgb scale = m.method == Method::C1Quadratic || m.method == Method::CloughTocher ? around : own;
          for (int ch = 0; ch < 3; ++ch) {
            ASSERT_LE(std::abs(s.B[ch] - mesh.nodes[c].B[ch]), 64 * eps * elementAspect(mesh, e) * scale[ch])
                << m.name << ", node " << c << " of " << describe(mesh, e);
            nodeError = std::max(nodeError, std::abs(s.B[ch] - mesh.nodes[c].B[ch]) / mesh.nodes[c].B[ch]);
          }
        }
        bool below = false;
        for (int k = 0; k < 200; ++k) {
          const Sample s = interpolant->evaluate(e, randomPointIn(mesh, e, points));
          ASSERT_TRUE(finite(s)) << m.name << " in " << describe(mesh, e);
          for (int ch = 0; ch < 3; ++ch) {
            worst = std::max(worst, -s.B[ch] / around[ch]);
            worstOwn = std::max(worstOwn, -s.B[ch] / own[ch]);
            below |= s.B[ch] < 0.0;
          }
        }
        negative += below;
      }
      std::printf(
          "[ figures  ] 1e-8 .. 1e8, %-13s %-24s min B / (largest nodal B around) %8.3g, / (the element's own) "
          "%8.3g, negative in %3d of %zu elements; at the nodes, relative error up to %.2g\n",
          kind == 0 ? "random nodes," : "10^(16x - 8),", m.name.c_str(), -worst, -worstOwn, negative,
          mesh.elements.size(), nodeError);
      if (m.method == Method::Gouraud || m.method == Method::Bilinear) {
        EXPECT_EQ(negative, 0) << m.name;
      }
      // Measured: at most 0.096 of the neighbourhood's value (c1-quadratic on 10^(16x - 8)).
      EXPECT_LE(worst, 0.12) << m.name << " went below zero by " << worst
                             << " of the largest value around (0.096 measured)";
    }
  }
}

TEST(Extremes, NearlyCollinearGradientStencilsStayBounded) {
  // A strip one cap high: nodes (i h, 0) and (i h + h/2, delta), every stencil within delta of
  // a line. Linear data plus noise (sigma 1e-3): the least-squares gradients see the noise
  // divided by delta across the strip, but the strip is only delta wide, so B stays within a
  // few sigma of the data; below a spread of ~1e-6 the cross component is dropped (rank
  // threshold), costing at most |grad| delta. Asserted: |B - linear| <= 8 sigma + 2 |grad| delta.
  const double sigma = 1e-3;
  for (double delta : {1e-3, 1e-5, 1e-7}) {
    RadiosityMesh mesh;
    mesh.materials.push_back(Material{"grey", Rgb(0.5), Rgb(0.0)});
    const int n = 8;
    for (int i = 0; i <= n; ++i)
      mesh.nodes.push_back({plane.at(double(i) / n, 0.0), linear(Vec2(double(i) / n, 0.0)), {}});
    for (int i = 0; i < n; ++i) {
      const Vec2 p((i + 0.5) / n, delta);
      mesh.nodes.push_back({plane.at(p.x, p.y), linear(p), {}});
    }
    for (int i = 0; i < n; ++i) {
      const uint32_t top = uint32_t(n + 1 + i);
      mesh.elements.push_back(Element{{uint32_t(i), uint32_t(i + 1), top}, {}, 0, 0});
      if (i + 1 < n) mesh.elements.push_back(Element{{uint32_t(i + 1), top + 1, top}, {}, 0, 0});
    }
    addNoise(mesh, sigma, 3);
    double gradient = 0.0;
    for (const Vec2& g : kLinearSlope) gradient = std::max(gradient, glm::length(g));
    for (const MethodCase& m : allMethods(false)) {
      const auto interpolant = makeInterpolant(mesh, m.method, m.options);
      std::mt19937 random(5);
      double worst = 0.0;
      for (uint32_t e = 0; e < mesh.elements.size(); ++e)
        for (int k = 0; k < 100; ++k) {
          const Vec3 x = randomPointIn(mesh, e, random);
          const Sample s = interpolant->evaluate(e, x);
          ASSERT_TRUE(finite(s)) << m.name;
          worst = std::max(worst, glm::length(s.B - linear(plane.coords(x))));
        }
      EXPECT_LE(worst, 8 * sigma + 2 * gradient * delta) << "strip " << delta << " high, " << m.name;
    }
  }
}

TEST(Extremes, ZeroAreaTrianglesGiveNeitherNaNNorAnAbort) {
  // validateMesh refuses zero-area elements in files; meshes built in code can hold them. What
  // happens, pinned: the element-local methods (linear, bilinear, quadratic) refuse the mesh
  // with an Error from makeInterpolant (their triangulation needs an area); the C1 methods
  // accept a zero-area triangle (its patch is linear along its longest edge, see
  // BarycentricFrame) and stay finite everywhere; a zero-area quad is refused by all. Before
  // the fix in vertex_gradients.cpp, two coincident nodes made the C1 methods with estimated
  // gradients abort (a NaN gradient from the zero normal of the degenerate triangle).
  for (int kind = 0; kind < 4; ++kind) {
    const bool quads = kind == 3;
    RadiosityMesh mesh = gridMesh(4, quads, 0.2, linear, 41, plane);
    const uint32_t a = 6, b = 7, c = 11;  // interior nodes (1, 1), (2, 1), (1, 2)
    if (kind == 0 || kind == 3) mesh.nodes[a].position = mesh.nodes[b].position;                      // coincident
    if (kind == 1) mesh.nodes[a].position = 0.5 * (mesh.nodes[b].position + mesh.nodes[c].position);  // collinear
    if (kind == 2) mesh.nodes[a].position = mesh.nodes[b].position = mesh.nodes[c].position;          // a point
    setValues(mesh, linear, plane);
    setGradients(mesh, linearGradient, plane);
    for (bool stored : {true, false}) {
      mesh.hasGradients = stored;
      for (const MethodCase& m : allMethods(true)) {
        const bool c1 = m.method == Method::C1Quadratic || m.method == Method::CloughTocher;
        const std::string input = "kind " + std::to_string(kind) + ", " + m.name;
        if (!c1 || quads) {
          EXPECT_THROW(makeInterpolant(mesh, m.method, m.options), Error) << input;
          continue;
        }
        const auto interpolant = makeInterpolant(mesh, m.method, m.options);
        std::mt19937 random(1);
        for (uint32_t e = 0; e < mesh.elements.size(); ++e)
          for (int k = 0; k < 20; ++k) {
            const Vec3 x = randomPointIn(mesh, e, random);
            const Sample s = interpolant->evaluate(e, x);
            ASSERT_TRUE(finite(s)) << input << ", " << describe(mesh, e);
            // Linear data stays linear to round-off away from the collapsed nodes' triangles.
            if (elementHeight(mesh, e) > 0.05) {
              EXPECT_LT(glm::length(s.B - linear(plane.coords(x))), 1e-12) << input << ", " << describe(mesh, e);
            }
          }
      }
    }
  }
}

TEST(Extremes, BilinearAndSerendipityQuadsFallBackToLinearOnNonConvexQuads) {
  // One quad with a reflex corner (from a jittered grid, seed 14 of reproduction_test). Its
  // bilinear map folds, and Newton's inverse of a folded map can wander off (B off by 66 on
  // data of size 6 at its own corners): such a quad is interpolated linearly, so its corners
  // are interpolated and linear data reproduced.
  RadiosityMesh mesh;
  mesh.materials.push_back(Material{"grey", Rgb(0.5), Rgb(0.0)});
  for (const Vec2& p : {Vec2(0.84, 2.29), Vec2(1.77, 1.80), Vec2(1.71, 3.25), Vec2(1.29, 2.72)})
    mesh.nodes.push_back({plane.at(p.x / 6, p.y / 6), linear(p / 6.0), {}});
  mesh.elements.push_back(Element{{0, 1, 2, 3}, {}, 0, 0});
  validateMesh(mesh, "non-convex quad");
  const RadiosityMesh quadratic = withMidEdgeNodes(mesh, linear, plane);
  for (const MethodCase& m :
       {MethodCase{"bilinear", Method::Bilinear, {}}, MethodCase{"quadratic", Method::Quadratic, {}}}) {
    const RadiosityMesh& used = m.method == Method::Quadratic ? quadratic : mesh;
    const auto interpolant = makeInterpolant(used, m.method);
    for (const Node& n : used.nodes)  // corners, and for the quadratic quad its mid-edge nodes (linear data)
      EXPECT_LT(glm::length(interpolant->evaluate(0, n.position).B - n.B), 1e-14) << m.name;
    std::mt19937 random(1);
    for (int k = 0; k < 50; ++k) {
      const Vec3 x = randomPointIn(used, 0, random);
      EXPECT_LT(glm::length(interpolant->evaluate(0, x).B - linear(plane.coords(x))), 1e-14)
          << m.name << " at " << str(x);
    }
  }
}

}  // namespace
}  // namespace radview
