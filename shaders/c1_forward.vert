#version 450 core
// The C1 methods per pixel in one pass (renderer/gl/deferred_pass.h), for draws with fewer
// vertices than the image has pixels.
layout(location = 0) in vec3 position;

uniform mat4 clipFromWorld;

out vec3 vLambda;  // perspective-correct: barycentric coordinates on the surface

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
// C1 quadratic: each vertex reads its triangle's packed values once, as flat outputs.
layout(binding = 1) uniform samplerBuffer nets;
flat out vec4 vNet[NET_VEC4S];

void main() {
  gl_Position = clipFromWorld * vec4(position, 1.0);
  int corner = gl_VertexID % 3;
  vLambda = vec3(corner == 0, corner == 1, corner == 2);
  // From the vertex index, not gl_PrimitiveID: llvmpipe gets the latter wrong in large draws.
  int first = (gl_VertexID / 3) * NET_VEC4S;
  for (int i = 0; i < NET_VEC4S; ++i) vNet[i] = texelFetch(nets, first + i);
}
#endif
