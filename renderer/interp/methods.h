#pragma once
// Constructors of the interpolation methods, one per file; makeInterpolant chooses.
#include "interp/interpolant.h"

#include <memory>

namespace radview {

std::unique_ptr<Interpolant> makeFlat(const RadiosityMesh& mesh);
std::unique_ptr<Interpolant> makeGouraud(const RadiosityMesh& mesh, QuadDiagonal diagonal);
std::unique_ptr<Interpolant> makeScanlineGouraud(const RadiosityMesh& mesh, const ScreenView& view);
std::unique_ptr<Interpolant> makeBilinear(const RadiosityMesh& mesh);
std::unique_ptr<Interpolant> makeQuadraticLagrange(const RadiosityMesh& mesh);
std::unique_ptr<Interpolant> makeC1Quadratic(const RadiosityMesh& mesh, const InterpolantOptions& options);
std::unique_ptr<Interpolant> makeCloughTocher(const RadiosityMesh& mesh, const InterpolantOptions& options);
std::unique_ptr<Interpolant> makeThinPlate(const RadiosityMesh& mesh, const InterpolantOptions& options);

}  // namespace radview
