#pragma once
// Whether this OpenGL interpolates varyings over triangles whose corners it has snapped to its
// sub-pixel grid, as GPUs do (Mesa's llvmpipe interpolates from the corners as given), and so
// whether the per-pixel methods must move what they interpolate to the pixel centre
// (shaders/lib/pixel_centre.glsl), which costs llvmpipe up to half a Gouraud frame.
namespace radview::gl {

// The probe's error above which corners count as snapped: between float rounding (1.1e-7 on
// llvmpipe) and a snapped grid (2.4e-4 at 1/256 pixel on an H200, about 1.5e-5 even at 1/4096),
// and below the per-pixel tests' tolerance of 1e-5.
constexpr double kSnappedInterpolationError = 2e-6;

// Probed once per process, on the current context, by drawing one small triangle whose corners
// lie off every sub-pixel grid and comparing its interpolated barycentric coordinates with
// the pixel centres' own (computed in double): more than kSnappedInterpolationError apart
// means snapped.
// RADVIEW_PIXEL_CENTRE=on or off overrides the probe (the tests run both). Throws Error for
// another value.
bool pixelCentreCorrection();

// The probe itself: the largest difference it finds between interpolated and exact barycentric
// coordinates (about 1e-7 where corners are not snapped, 1e-4 where they are); NaN if it could
// not draw. Leaves the context's state as it found it (bindings, viewport, capabilities,
// polygon mode, colour mask, pack state).
double rasteriserInterpolationError();

}  // namespace radview::gl
