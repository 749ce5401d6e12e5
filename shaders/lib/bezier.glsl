// Triangular Bezier patches of degree 2 or 3 (C&W eq. 9.7), the GLSL twin of
// renderer/interp/bezier_triangle.h:
//   B(beta) = sum_{i+j+k=n} n!/(i! j! k!) beta_u^i beta_v^j beta_w^k b_ijk,
// control values b_ijk in the same order (descending i, then descending j), RGB stored three
// floats each into vec4s.
// Control value `index` (for the tessellation level, which reads the net by loops).
vec3 bezierControl(vec4 net[8], int index) {
  int f = 3 * index;
  return vec3(net[f / 4][f % 4], net[(f + 1) / 4][(f + 1) % 4], net[(f + 2) / 4][(f + 2) % 4]);
}

// The Bernstein sums written out (C&W eq. 9.7) with constant indices: llvmpipe turns them into
// register reads, where a loop over the net indexes the varyings dynamically and costs
// several times as much per pixel.
vec3 quadraticBernstein(vec3 c[6], vec3 beta) {
  float u = beta.x, v = beta.y, w = beta.z;
  return u * u * c[0] + 2.0 * u * v * c[1] + 2.0 * u * w * c[2] + v * v * c[3] + 2.0 * v * w * c[4] + w * w * c[5];
}

vec3 cubicBernstein(vec3 c[10], vec3 beta) {
  float u = beta.x, v = beta.y, w = beta.z;
  return u * u * u * c[0] + 3.0 * u * u * v * c[1] + 3.0 * u * u * w * c[2] + 3.0 * u * v * v * c[3] +
         6.0 * u * v * w * c[4] + 3.0 * u * w * w * c[5] + v * v * v * c[6] + 3.0 * v * v * w * c[7] +
         3.0 * v * w * w * c[8] + w * w * w * c[9];
}

vec3 quadraticBezier(vec4 net[8], vec3 beta) {
  vec3 c[6] = vec3[](net[0].xyz, vec3(net[0].w, net[1].xy), vec3(net[1].zw, net[2].x), net[2].yzw, net[3].xyz,
                     vec3(net[3].w, net[4].xy));
  return quadraticBernstein(c, beta);
}

vec3 cubicBezier(vec4 net[8], vec3 beta) {
  vec3 c[10] = vec3[](net[0].xyz, vec3(net[0].w, net[1].xy), vec3(net[1].zw, net[2].x), net[2].yzw, net[3].xyz,
                      vec3(net[3].w, net[4].xy), vec3(net[4].zw, net[5].x), net[5].yzw, net[6].xyz,
                      vec3(net[6].w, net[7].xy));
  return cubicBernstein(c, beta);
}

// Degree DEGREE, a macro the program defines: 3 (Clough-Tocher) or 2 (Powell-Sabin, quadratic
// Lagrange). A compile-time choice, as llvmpipe pays for both sides of a branch on a uniform.
vec3 bezierTriangle(vec4 net[8], vec3 beta) {
#if DEGREE == 3
  return cubicBezier(net, beta);
#else
  return quadraticBezier(net, beta);
#endif
}
