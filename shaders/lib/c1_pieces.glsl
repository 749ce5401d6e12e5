// The C1 methods' value at barycentric coordinates lambda of an element triangle, from its
// packed values (renderer/gl/patch_nets.h, NET_VEC4S vec4): the GLSL twin of evaluate() in
// renderer/interp/clough_tocher.cpp (DEGREE 3) and renderer/interp/powell_sabin.cpp
// (DEGREE 2). Needs lib/bezier.glsl included before it.

// The smallest of three, the first of equals (the CPU's comparisons, in the same order).
int smallest(vec3 v) { return v.x <= v.y ? (v.x <= v.z ? 0 : 2) : (v.y <= v.z ? 1 : 2); }

// One of three by index, as selects (a local array indexed at run time costs more on llvmpipe).
vec3 pick(int i, vec3 a, vec3 b, vec3 c) { return i == 0 ? a : (i == 1 ? b : c); }

#if DEGREE == 3
// Clough-Tocher (C&W §9.2.2, fig. 9.12): piece k = o + 1 holds the point where lambda_o is the
// smallest, at coordinates (lambda_k - lambda_o, lambda_k1 - lambda_o, 3 lambda_o). The packed
// values (patch_nets.h) are f, the tangent-plane values b210 and b120 along each outer edge,
// and each piece's b111; the rest are the C1 conditions inside the triangle, as
// clough_tocher.cpp's buildCloughTocher forms them: on the inner edge V_i - C next to V_i the
// mean of V_i's tangent-plane values (step 2), next to C the mean of that and the b111 on
// either side (step 4), and at C the mean of those three.
vec3 c1Value(vec4 n[NET_VEC4S], vec3 lambda) {
  vec3 f0 = n[0].xyz, f1 = vec3(n[0].w, n[1].xy), f2 = vec3(n[1].zw, n[2].x);
  vec3 b01 = n[2].yzw, b10 = n[3].xyz, b12 = vec3(n[3].w, n[4].xy), b21 = vec3(n[4].zw, n[5].x);
  vec3 b20 = n[5].yzw, b02 = n[6].xyz, c0 = vec3(n[6].w, n[7].xy), c1 = vec3(n[7].zw, n[8].x), c2 = n[8].yzw;
  vec3 inner0 = (f0 + b01 + b02) / 3.0, inner1 = (f1 + b12 + b10) / 3.0, inner2 = (f2 + b20 + b21) / 3.0;
  vec3 d0 = (inner0 + c0 + c2) / 3.0, d1 = (inner1 + c1 + c0) / 3.0, d2 = (inner2 + c2 + c1) / 3.0;
  int o = smallest(lambda), k = (o + 1) % 3, k1 = (o + 2) % 3;
  vec3 c[10] = vec3[](pick(k, f0, f1, f2), pick(k, b01, b12, b20), pick(k, inner0, inner1, inner2),
                      pick(k, b10, b21, b02), pick(k, c0, c1, c2), pick(k, d0, d1, d2), pick(k1, f0, f1, f2),
                      pick(k1, inner0, inner1, inner2), pick(k1, d0, d1, d2), (d0 + d1 + d2) / 3.0);
  return cubicBernstein(c, vec3(lambda[k] - lambda[o], lambda[k1] - lambda[o], 3.0 * lambda[o]));
}
#else
// Powell-Sabin (C&W §9.2.2, fig. 9.9; Reichert): the fan triangle (V_k, V_k1, Z) with the
// smallest mu = lambda_o / zeta_o, then the side of the line Z - R_k, as powell_sabin.cpp's
// evaluate chooses. The control values are buildPowellSabin's, from the corner values f and
// the derivatives along the edges packed with them (patch_nets.h): at (V_k + R_k)/2 f_k +
// t_k D_k / 2, at (V_k1 + R_k)/2 f_k1 + (1 - t_k) E_k / 2, at (V_i + Z)/2 f_i + (zeta_i+1 D_i +
// zeta_i+2 E_i+2) / 2 (Z - V_i along the two edges from V_i), and the means between them.
vec3 c1Value(vec4 n[NET_VEC4S], vec3 lambda) {
  vec3 zeta = vec3(n[0].w, n[1].w, n[2].w);
  vec3 z0 = n[0].xyz + 0.5 * (zeta.y * n[3].xyz + zeta.z * n[8].xyz);
  vec3 z1 = n[1].xyz + 0.5 * (zeta.z * n[4].xyz + zeta.x * n[6].xyz);
  vec3 z2 = n[2].xyz + 0.5 * (zeta.x * n[5].xyz + zeta.y * n[7].xyz);
  int o = smallest(lambda / zeta), k = (o + 1) % 3, k1 = (k + 1) % 3;
  float t = vec3(n[3].w, n[4].w, n[5].w)[k];
  vec3 fk = pick(k, n[0].xyz, n[1].xyz, n[2].xyz), fk1 = pick(k1, n[0].xyz, n[1].xyz, n[2].xyz);
  vec3 nearR = fk + 0.5 * t * pick(k, n[3].xyz, n[4].xyz, n[5].xyz);
  vec3 farR = fk1 + 0.5 * (1.0 - t) * pick(k, n[6].xyz, n[7].xyz, n[8].xyz);
  vec3 zk = pick(k, z0, z1, z2), zk1 = pick(k1, z0, z1, z2);
  float mu = lambda[o] / zeta[o];
  float a = lambda[k] - mu * zeta[k], b = lambda[k1] - mu * zeta[k1];
  bool nearSide = b * (1.0 - t) <= a * t;
  vec3 c[6] = vec3[](nearSide ? fk : fk1, nearSide ? nearR : farR, nearSide ? zk : zk1, (1.0 - t) * nearR + t * farR,
                     (1.0 - t) * zk + t * zk1, zeta.x * z0 + zeta.y * z1 + zeta.z * z2);
  vec3 sigma = nearSide ? vec3(a - b * (1.0 - t) / t, b / t, mu) : vec3(b - a * t / (1.0 - t), a / (1.0 - t), mu);
  return quadraticBernstein(c, sigma);
}
#endif
