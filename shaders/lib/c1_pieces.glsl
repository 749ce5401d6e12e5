// The C1 methods' value at barycentric coordinates lambda of an element triangle, from its
// packed values (renderer/gl/patch_nets.h, NET_VEC4S vec4): the GLSL twin of evaluate() in
// renderer/interp/clough_tocher.cpp (DEGREE 3) and renderer/interp/powell_sabin.cpp
// (DEGREE 2). Needs lib/bezier.glsl included before it.

// The smallest of three, the first of equals (the CPU's comparisons, in the same order).
int smallest(vec3 v) { return v.x <= v.y ? (v.x <= v.z ? 0 : 2) : (v.y <= v.z ? 1 : 2); }

#if DEGREE == 3
// Clough-Tocher (C&W §9.2.2, fig. 9.12) as patch_nets.h packs it: the cubic P of the piece
// where lambda_0 is the smallest, over the whole triangle, plus alpha psi_1 + beta psi_2, the
// C1 corrections that make it the piece where lambda_1 or lambda_2 is the smallest. P's
// control values come scaled by their Bernstein weights 3!/(i! j! k!), each held by a corner
// k whose lambda_k divides its monomial: P = S_uu u^2 + S_vv v^2 + S_ww w^2 + S_uw u w in
// (u, v, w) = lambda, each S the sum over corners of lambda_k times the corner's value, that
// is, the linear interpolation of the corners' values (patch_nets.h lists them). The one-pass
// shader gets the S as interpolated outputs, so that each vertex reads only its own corner.
vec3 cubicFromSums(vec3 lambda, vec3 uu, vec3 vv, vec3 ww, vec3 uw) {
  float u = lambda.x, v = lambda.y, w = lambda.z;
  return (u * u) * uu + (v * v) * vv + (w * w) * ww + (u * w) * uw;
}

// alpha psi_1 + beta psi_2 at lambda (patch_nets.h).
vec3 cloughTocherCorrection(vec3 lambda, vec3 alpha, vec3 beta) {
  float u = lambda.x, v = lambda.y, w = lambda.z;
  int o = smallest(lambda);
  float across = o == 0 ? 0.0 : (o == 1 ? v - u : w - u);
  float wAlpha = o == 1 ? u + v - 2.0 * w : u - v;
  float wBeta = o == 1 ? w - u : 2.0 * v - u - w;
  return (across * across) * (wAlpha * alpha + wBeta * beta);
}

// The value from the packed values of the whole triangle (the deferred pass): corner k's
// values are vec3 4 k .. 4 k + 3, corner 2's first and last being alpha and beta.
vec3 c1Value(vec4 n[NET_VEC4S], vec3 lambda) {
  vec3 c[12] = vec3[](n[0].xyz, vec3(n[0].w, n[1].xy), vec3(n[1].zw, n[2].x), n[2].yzw, n[3].xyz,
                      vec3(n[3].w, n[4].xy), vec3(n[4].zw, n[5].x), n[5].yzw, n[6].xyz, vec3(n[6].w, n[7].xy),
                      vec3(n[7].zw, n[8].x), n[8].yzw);
  float u = lambda.x, v = lambda.y, w = lambda.z;
  return cubicFromSums(lambda, u * c[0] + v * c[4], u * c[1] + v * c[5] + w * c[9], u * c[2] + v * c[6] + w * c[10],
                       u * c[3] + v * c[7]) +
         cloughTocherCorrection(lambda, c[8], c[11]);
}
#else
// Powell-Sabin (C&W §9.2.2, fig. 9.9; Reichert) as patch_nets.h packs it: the quadratic Q with
// the corner values f and the derivatives D_k along each edge k from its first corner, plus
// the Powell-Sabin spline with those 0 and, along each edge from its second corner, the
// derivative e_k by which the element's differs from Q's: the spline reproduces quadratics
// and is linear in its data. Q = u S_u + v S_v + w S_w in (u, v, w) = lambda, each S the
// linear interpolation of the corners' values, as for Clough-Tocher above.
vec3 quadraticFromSums(vec3 lambda, vec3 su, vec3 sv, vec3 sw) { return lambda.x * su + lambda.y * sv + lambda.z * sw; }

// The rest: in the fan triangle (V_k, V_k1, Z) with the smallest mu = lambda_o / zeta_o, as
// powell_sabin.cpp's evaluate chooses, whose barycentric coordinates are (a_k, a_k1, mu) with
// a = lambda - mu zeta (a_o = 0), the two pieces on either side of the line Z - R_k,
// R_k = (1 - t_k) V_k + t_k V_k1. Their control values, as buildPowellSabin's with f = D = 0:
// at (V_k1 + R_k)/2 (1 - t_k) e_k / 2, at (V_i + Z)/2 zeta_i+2 e_i+2 / 2 (Z - V_i along the
// edge into V_i), the means between them, 0 elsewhere. Summed in Bernstein form they reduce to
// one weight per e_i: mu^2 zeta_i zeta_i+1 / 2 from Z, and
//   e_o: mu zeta_o a_k;   e_k: mu zeta_k a_k1 + g^2 / (2 t (1 - t)), g = (1 - t) a_k1, t = t_k,
// on the side of V_k; beyond the line, the C1 join subtracts (g - a_k t)^2 / (2 t (1 - t)),
// which leaves min(g, a_k t) max(g, 2 g - a_k t) / (2 t (1 - t)) on both sides. Written for
// every i at once these terms vanish for the corners they do not belong to (a_o = 0), so no
// piece is chosen: mu is the smallest quotient, whichever fan it names.
vec3 powellSabinRest(vec3 lambda, vec3 e0, vec3 e1, vec3 e2, vec3 zeta, vec3 split) {
  vec3 quotients = lambda / zeta;
  float mu = min(min(quotients.x, quotients.y), quotients.z);
  vec3 a = lambda - mu * zeta, aNext = a.yzx;
  vec3 g = (1.0 - split) * aNext, at = a * split;
  vec3 w = mu * zeta * aNext + 0.5 * min(g, at) * max(g, 2.0 * g - at) / (split * (1.0 - split)) +
           (0.5 * mu * mu) * (zeta * zeta.yzx);
  return w.x * e0 + w.y * e1 + w.z * e2;
}

// The value from the packed values of the whole triangle (the deferred pass): corner k's 12
// floats from 12 k are its two values of the sums, e_k and t_k; floats 10 and 11 zeta_0 and
// zeta_1.
vec3 c1Value(vec4 n[NET_VEC4S], vec3 lambda) {
  vec3 a0 = n[0].xyz, b0 = vec3(n[0].w, n[1].xy), e0 = vec3(n[1].zw, n[2].x);
  vec3 a1 = n[3].xyz, b1 = vec3(n[3].w, n[4].xy), e1 = vec3(n[4].zw, n[5].x);
  vec3 a2 = n[6].xyz, b2 = vec3(n[6].w, n[7].xy), e2 = vec3(n[7].zw, n[8].x);
  float u = lambda.x, v = lambda.y, w = lambda.z;
  return quadraticFromSums(lambda, u * a0 + v * a1, v * b1 + w * a2, u * b0 + w * b2) +
         powellSabinRest(lambda, e0, e1, e2, vec3(n[2].zw, 1.0 - n[2].z - n[2].w), vec3(n[2].y, n[5].y, n[8].y));
}
#endif
