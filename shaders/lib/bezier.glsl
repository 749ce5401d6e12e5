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
vec3 quadraticBezier(vec4 net[8], vec3 beta) {
  float u = beta.x, v = beta.y, w = beta.z;
  vec3 c0 = net[0].xyz, c1 = vec3(net[0].w, net[1].xy), c2 = vec3(net[1].zw, net[2].x);
  vec3 c3 = net[2].yzw, c4 = net[3].xyz, c5 = vec3(net[3].w, net[4].xy);
  return u * u * c0 + 2.0 * u * v * c1 + 2.0 * u * w * c2 + v * v * c3 + 2.0 * v * w * c4 + w * w * c5;
}

vec3 cubicBezier(vec4 net[8], vec3 beta) {
  float u = beta.x, v = beta.y, w = beta.z;
  vec3 c0 = net[0].xyz, c1 = vec3(net[0].w, net[1].xy), c2 = vec3(net[1].zw, net[2].x), c3 = net[2].yzw;
  vec3 c4 = net[3].xyz, c5 = vec3(net[3].w, net[4].xy), c6 = vec3(net[4].zw, net[5].x), c7 = net[5].yzw;
  vec3 c8 = net[6].xyz, c9 = vec3(net[6].w, net[7].xy);
  return u * u * u * c0 + 3.0 * u * u * v * c1 + 3.0 * u * u * w * c2 + 3.0 * u * v * v * c3 +
         6.0 * u * v * w * c4 + 3.0 * u * w * w * c5 + v * v * v * c6 + 3.0 * v * v * w * c7 +
         3.0 * v * w * w * c8 + w * w * w * c9;
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
