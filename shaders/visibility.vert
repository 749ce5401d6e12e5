#version 450 core
#include "lib/eye_plane.glsl"
// The deferred per-pixel pass's raster (renderer/gl/deferred_pass.h): each element triangle
// once, as Gouraud draws them, carrying only which triangle it is and where in it a pixel is.
layout(location = 0) in vec3 position;

uniform mat4 clipFromWorld;

out vec3 vLambda;  // perspective-correct: barycentric coordinates on the surface
out vec4 vClip;    // and the clip position of their surface point (lib/pixel_centre.glsl)
flat out uint vTriangle;

void main() {
  gl_Position = clipFromWorld * vec4(position, 1.0);
  clipBehindTheEye();
  int corner = gl_VertexID % 3;
  vLambda = vec3(corner == 0, corner == 1, corner == 2);
  vClip = gl_Position;
  // From the vertex index, not gl_PrimitiveID: llvmpipe gets the latter wrong in large draws.
  vTriangle = uint(gl_VertexID / 3);
}
