#version 450 core
#include "lib/eye_plane.glsl"
// Overlay lines and markers with a colour per vertex (discontinuity edges, T-vertices).
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 colour;
uniform mat4 clipFromWorld;
uniform float pointSize;
out vec4 vColour;
void main() {
  gl_Position = clipFromWorld * vec4(position, 1.0);
  clipBehindTheEye();
  gl_PointSize = pointSize;
  vColour = colour;
}
