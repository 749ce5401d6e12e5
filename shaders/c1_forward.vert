#version 450 core
// The C1 methods per pixel in one pass (renderer/gl/deferred_pass.h), for draws with fewer
// vertices than the image has pixels: each vertex reads its triangle's packed values once, as
// flat outputs, where the deferred pass reads them once per covered pixel. (Completing
// Clough-Tocher's control values here instead of per pixel made 19 flat outputs of 9 and cost
// more than it saved on llvmpipe.)
layout(location = 0) in vec3 position;
layout(binding = 1) uniform samplerBuffer nets;

uniform mat4 clipFromWorld;

out vec3 vLambda;  // perspective-correct: barycentric coordinates on the surface
flat out vec4 vNet[NET_VEC4S];

void main() {
  gl_Position = clipFromWorld * vec4(position, 1.0);
  int corner = gl_VertexID % 3;
  vLambda = vec3(corner == 0, corner == 1, corner == 2);
  // From the vertex index, not gl_PrimitiveID: llvmpipe gets the latter wrong in large draws.
  int first = (gl_VertexID / 3) * NET_VEC4S;
  for (int i = 0; i < NET_VEC4S; ++i) vNet[i] = texelFetch(nets, first + i);
}
