#pragma once
// An approximating reconstruction (C&W §9.2, last paragraph: nodal values are noisy samples, and
// a function that does not pass through every one of them can be the better picture): a
// thin-plate smoothing spline of the nodal values, fitted on the mesh itself, whose values then
// feed the Clough-Tocher patches (Method::ThinPlate).
//
// In each region (the elements of one surface joined through shared nodes: C-1 edges, whose two
// sides have nodes of their own, bound regions) the fitted values f minimise
//
//   sum_i w_i |f_i - B_i|^2  +  lambda E(f),    E(f) = sum_e c_e (jump_e)^2,
//
// over the region's piecewise linear functions (its elements triangulated conformingly,
// T-vertices included). jump_e is the jump of the normal derivative across interior edge e (a
// piecewise linear function bends only there), c_e = 2 l_e^2 / (A_1 + A_2) from the edge's
// length and its two triangles' areas. On a regular mesh E tends to the thin-plate energy
// integral of |Hess f|^2 (up to boundary terms); it is 0 exactly for linear f, so linear data
// are kept for every lambda. Edges tagged C0 are left out of E (a kink costs nothing there), as
// are the region's boundary edges (natural boundary conditions, as a thin plate's). Weights w
// come from the nodes' standard errors, w = 1 / (SE^2 + s0^2), s0 half the region's RMS standard
// error (a node the solver found exact still gets a finite weight: its estimate can miss), scaled
// to mean 1; without standard errors all are 1. lambda is given, or chosen per region by
// generalised cross-validation (Craven & Wahba 1979; each degree of freedom charged 1.4 times,
// as Kim & Gu 2004 advise against undersmoothing), the influence matrix's trace estimated from
// random probes where the region is large (Hutchinson 1990); a region above 12,000 nodes is
// cross-validated in pieces of it, then fitted whole (thin_plate_region.h). Where cross-validation cannot tell
// noise from signal (a small region; the best score next to the pole of the degrees of freedom
// charged: no noise found) the values are kept. The sparse systems
// (W + lambda Q) f = W B are solved by Eigen's supernodal sparse LU, one factorisation per
// lambda serving R, G, B and the probes; the walk over lambda follows GCV's slope, which the
// same factorisation gives.
#include "mesh/radiosity_mesh.h"
#include "mesh/topology.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace radview {

struct ThinPlateSettings {
  std::optional<double> lambda;  // none: by generalised cross-validation in each region
};

// "auto" (by cross-validation) or lambda, a number >= 0 (0: the data themselves). Throws Error.
ThinPlateSettings thinPlateSettingsFromText(const std::string& text);

struct ThinPlateRegion {
  size_t nodes = 0;
  int surface = -1;
  double lambda = 0.0;
  double effectiveDof = 0.0;  // trace of the influence matrix: nodes' worth of freedom kept
  bool smoothed = false;      // false: too few nodes to bend, or an emitter (values kept)
};

struct ThinPlateReport {
  std::vector<ThinPlateRegion> regions;
};

// The mesh with every node's B replaced by the fit (gradients dropped, to be estimated from the
// fitted values; standard errors dropped). `topology` is the mesh's own. `weights`, when given,
// replaces the standard errors' weights: one per node, finite and >= 0 (Error otherwise). A
// node shared by several regions gets the mean of their fits. Regions are fitted on every core.
RadiosityMesh smoothThinPlate(const RadiosityMesh& mesh, const MeshTopology& topology,
                              const ThinPlateSettings& settings, ThinPlateReport* report = nullptr,
                              const std::vector<double>* weights = nullptr);

}  // namespace radview
