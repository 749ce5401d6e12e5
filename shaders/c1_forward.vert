#version 450 core
#include "lib/eye_plane.glsl"
// The C1 methods per pixel in one pass (renderer/gl/deferred_pass.h), for draws with fewer
// vertices than the image has pixels.
layout(location = 0) in vec3 position;

uniform mat4 clipFromWorld;

out vec3 vLambda;  // perspective-correct: barycentric coordinates on the surface
out vec4 vClip;    // and the clip position of their surface point (lib/pixel_centre.glsl)

#if DEGREE == 3
// Clough-Tocher: each vertex carries its own corner's 12 floats (lib/c1_pieces.glsl) as
// vertex attributes and passes them as interpolated outputs, which sum the corners' values
// weighted by lambda; alpha and beta, held by the third corner, are flat (the last vertex's).
// A triangle reads its 144 bytes once, not three times.
layout(location = 1) in vec4 corner0;
layout(location = 2) in vec4 corner1;
layout(location = 3) in vec4 corner2;
out vec3 vUU, vVV, vWW, vUW;
flat out vec3 vAlpha, vBeta;

void main() {
  gl_Position = clipFromWorld * vec4(position, 1.0);
  clipBehindTheEye();
  vClip = gl_Position;
  int corner = gl_VertexID % 3;
  vLambda = vec3(corner == 0, corner == 1, corner == 2);
  vec3 first = corner0.xyz, last = corner2.yzw;
  vUU = corner == 2 ? vec3(0.0) : first;
  vVV = vec3(corner0.w, corner1.xy);
  vWW = vec3(corner1.zw, corner2.x);
  vUW = corner == 2 ? vec3(0.0) : last;
  vAlpha = first;
  vBeta = last;
}
#else
// C1 quadratic: likewise each vertex reads its corner's two values of the sums; e, zeta and t
// are flat, the first vertex's, which reads them from the other corners' 12 floats too: five
// vec4 a vertex in all, where its triangle's values as texels took nine.
layout(location = 1) in vec4 own0;  // floats 0-3 of the corner's 12
layout(location = 2) in vec4 own1;  // 4-7
layout(location = 3) in vec4 own2;  // 8-11
layout(location = 4) in vec4 next;  // 18-21: the next corner's e and t
layout(location = 5) in vec4 last;  // 30-33: the last corner's
out vec3 vSumU, vSumV, vSumW;
flat out vec3 vE0, vE1, vE2, vZeta, vSplit;

void main() {
  gl_Position = clipFromWorld * vec4(position, 1.0);
  clipBehindTheEye();
  vClip = gl_Position;
  int corner = gl_VertexID % 3;
  vLambda = vec3(corner == 0, corner == 1, corner == 2);
  vec3 a = own0.xyz, b = vec3(own0.w, own1.xy);
  vSumU = corner == 2 ? vec3(0.0) : a;
  vSumV = corner == 0 ? vec3(0.0) : (corner == 1 ? b : a);
  vSumW = corner == 1 ? vec3(0.0) : b;
  vE0 = vec3(own1.zw, own2.x);
  vE1 = next.xyz;
  vE2 = last.xyz;
  vZeta = vec3(own2.zw, 1.0 - own2.z - own2.w);
  vSplit = vec3(own2.y, next.w, last.w);
}
#endif
