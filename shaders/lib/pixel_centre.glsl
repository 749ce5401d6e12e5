// The surface point of this fragment's pixel centre, exactly, for the per-pixel methods.
// A GPU's rasteriser snaps a triangle's corners to its sub-pixel grid (GL_SUBPIXEL_BITS, 8 on
// current GPUs) and interpolates every varying over the snapped triangle: on a triangle a few
// pixels wide, barycentric coordinates move by up to 1e-4, and a value by 1e-5 of B ~ 0.5,
// ten times what the CPU reference (which traces the centre itself) allows per pixel.
// Every interpolated value of a triangle is the same affine function of its interpolated
// surface point X, on the triangle's plane, and so is X's clip position c. The pixel centre's
// own point is X + a dX/dx + b dX/dy in the pixel's screen derivatives, where (a, b) solve the
// two linear equations "it projects to the centre", c.xy = ndc c.w (in clip space: no inverse
// matrix, free of the scene's scale); an affine value moves by the same a dV/dx + b dV/dy.
// PIXEL_CENTRE_CORRECTION is defined by ShaderProgram from a probe of this OpenGL
// (gl/rasteriser_probe.h): 0 where varyings are interpolated from the corners as given (Mesa's
// llvmpipe), and then both are no-ops. Call pixelCentreStep in uniform control flow
// (derivatives), before any discard.
uniform vec2 viewportSize;  // the viewport's, at origin (0, 0)

#if PIXEL_CENTRE_CORRECTION
// (a, b) above, from the interpolated clip position c; (0, 0) where the derivatives span no plane.
vec2 pixelCentreStep(vec4 c) {
  vec4 cx = dFdxFine(c), cy = dFdyFine(c);
  vec2 ndc = gl_FragCoord.xy / viewportSize * 2.0 - 1.0;
  vec2 r = c.xy - ndc * c.w, ex = cx.xy - ndc * cx.w, ey = cy.xy - ndc * cy.w;
  float det = ex.x * ey.y - ey.x * ex.y;
  if (!(abs(det) > 0.0)) return vec2(0.0);
  return vec2(ey.x * r.y - r.x * ey.y, ex.y * r.x - ex.x * r.y) / det;
}

// An interpolated value affine on the surface, moved to the pixel centre (step: pixelCentreStep).
#define AT_PIXEL_CENTRE(value, step) ((value) + (step).x * dFdxFine(value) + (step).y * dFdyFine(value))
#else
#define pixelCentreStep(c) vec2(0.0)
#define AT_PIXEL_CENTRE(value, step) (value)
#endif
