#version 450 core
#include "lib/eye_plane.glsl"
// Radiosity mesh, triangulated: each vertex carries its node's radiosity B and the
// element's mean value for flat shading.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 B;
layout(location = 2) in vec3 Bflat;

uniform mat4 clipFromWorld;

out vec3 vB;  // perspective-correct: linear on the surface (C&W §9.2, footnote 3)
// Linear in screen space, as classic Gouraud hardware interpolated. Not the `noperspective`
// qualifier: Mesa llvmpipe 22.3 returns NaN for it on triangles clipped by the view volume.
// Perspective-correct interpolation of (B w, w) divided through is exactly the screen-space
// interpolation of B, and clipping handles it correctly since it is linear in clip space.
out vec4 vBw;
flat out vec3 vBFlat;

void main() {
  gl_Position = clipFromWorld * vec4(position, 1.0);
  clipBehindTheEye();
  vB = B;
  vBw = vec4(B * gl_Position.w, gl_Position.w);
  vBFlat = Bflat;
}
