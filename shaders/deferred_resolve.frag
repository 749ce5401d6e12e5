#version 450 core
#include "lib/bezier.glsl"
// The deferred per-pixel pass's evaluation: once per covered pixel, whatever the depth
// complexity, the exact value of the piece of its triangle that holds its surface point, the
// GLSL twin of evaluate() in renderer/interp/clough_tocher.cpp (DEGREE 3) and
// renderer/interp/powell_sabin.cpp (DEGREE 2). Control values come from a storage buffer laid
// out as renderer/gl/patch_nets.h says. Linear radiosity, like mesh.frag.
layout(binding = 0) uniform usampler2D visibility;
layout(binding = 1) uniform samplerBuffer nets;

layout(location = 0) out vec4 radiosity;

// The net of `count` vec4 from nets[first], zero after them.
void loadNet(uint first, const int count, out vec4 net[8]) {
  for (int i = 0; i < 8; ++i) net[i] = i < count ? texelFetch(nets, int(first) + i) : vec4(0.0);
}

// The smallest of three, the first of equals (the CPU's comparisons, in the same order).
int smallest(vec3 v) { return v.x <= v.y ? (v.x <= v.z ? 0 : 2) : (v.y <= v.z ? 1 : 2); }

void main() {
  uvec4 seen = texelFetch(visibility, ivec2(gl_FragCoord.xy), 0);
  if (seen.x == 0u) discard;
  vec3 lambda = uintBitsToFloat(seen.yzw);
  vec4 net[8];
#if DEGREE == 3
  uint base = (seen.x - 1u) * 24u;
  // Clough-Tocher: piece k = o + 1 holds the point where lambda_o is the smallest; its
  // coordinates are (lambda_k - lambda_o, lambda_k1 - lambda_o, 3 lambda_o).
  int o = smallest(lambda), k = (o + 1) % 3, k1 = (o + 2) % 3;
  loadNet(base + uint(8 * k), 8, net);
  vec3 sigma = vec3(lambda[k] - lambda[o], lambda[k1] - lambda[o], 3.0 * lambda[o]);
#else
  uint base = (seen.x - 1u) * 32u;
  // Powell-Sabin: the fan triangle (V_k, V_k1, Z) with the smallest mu = lambda_o / zeta_o,
  // then the side of the line Z - R_k, as powell_sabin.cpp's evaluate chooses.
  vec3 zeta = texelFetch(nets, int(base) + 30).xyz;
  int o = smallest(lambda / zeta), k = (o + 1) % 3, k1 = (k + 1) % 3;
  float t = texelFetch(nets, int(base) + 31)[k];
  float mu = lambda[o] / zeta[o];
  float a = lambda[k] - mu * zeta[k], b = lambda[k1] - mu * zeta[k1];
  bool first = b * (1.0 - t) <= a * t;
  loadNet(base + uint(5 * (first ? 2 * k : 2 * k + 1)), 5, net);
  vec3 sigma = first ? vec3(a - b * (1.0 - t) / t, b / t, mu) : vec3(b - a * t / (1.0 - t), a / (1.0 - t), mu);
#endif
  radiosity = vec4(bezierTriangle(net, sigma), 1.0);
}
