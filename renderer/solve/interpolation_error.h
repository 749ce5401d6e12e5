#pragma once
// How far linear interpolation is from the radiosity inside each element, estimated without a
// ray. Linear elements sample a curved B at their corners only: where light is bright and
// smooth, a coarse element's interpolant sags below a concave B (or bulges above a convex one)
// by a few percent without its corners differing much on display, so a spread criterion never
// splits it. Both the picture and the solve pay: the element's mean radiosity, which its patch
// shoots (progressive_refinement.h), is the interpolant's mean, so what the element reflects is
// off by the same amount.
//
// The estimate: at the element's centre, Clough-Tocher's value (C&W §9.2.2: cubic patches on
// nodal gradients fitted to the neighbouring nodes, which reproduce a quadratic B exactly) less
// the linear interpolant's (the corners' mean). For a quadratic B this is the linear
// interpolant's error at the centre; over a triangle its mean error is 3/4 of that.
#include "mesh/radiosity_mesh.h"

#include <vector>

namespace radview {

// Per element: |Y(B_CT(c)) - Y(B_linear(c))| / max(Y(B_linear(c)), floorY), Y the Rec. 709
// luminance, c the centroid of the element's corners. floorY keeps dark elements (umbrae) from
// asking for ever finer elements to resolve a relative error of light they barely have.
// Elements with fewer than 3 corners get 0. `valued` must pass validateMesh.
std::vector<double> relativeInterpolationErrors(const RadiosityMesh& valued, double floorY);

}  // namespace radview
