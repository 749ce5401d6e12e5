#version 450 core
// One Bezier piece of a C1 interpolant per triangle (renderer/gl/patch_vertices.h).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 beta;
layout(location = 2) in vec4 control[8];

uniform mat4 clipFromWorld;

out vec3 vBeta;  // perspective-correct: barycentric on the surface
flat out vec4 vControl[8];

void main() {
  gl_Position = clipFromWorld * vec4(position, 1.0);
  vBeta = beta;
  vControl = control;
}
