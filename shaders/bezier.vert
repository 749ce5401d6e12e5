#version 450 core
#include "lib/eye_plane.glsl"
// One Bezier piece of a C1 interpolant per triangle (renderer/gl/patch_vertices.h).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 beta;
layout(location = 2) in vec4 control[8];

uniform mat4 clipFromWorld;

out vec3 vBeta;  // perspective-correct: barycentric on the surface
out vec4 vClip;  // and the clip position of its surface point (lib/pixel_centre.glsl)
flat out vec4 vControl[8];

void main() {
  gl_Position = clipFromWorld * vec4(position, 1.0);
  clipBehindTheEye();
  vBeta = beta;
  vClip = gl_Position;
  vControl = control;
}
