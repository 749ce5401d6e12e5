#version 450 core
#include "lib/eye_plane.glsl"
layout(location = 0) in vec3 position;
uniform mat4 clipFromWorld;
void main() {
  gl_Position = clipFromWorld * vec4(position, 1.0);
  clipBehindTheEye();
}
