#version 450 core
// The element triangles (as for Gouraud), for the methods that need the whole element polygon
// per pixel: scanline Gouraud and bilinear. The polygon comes from a storage buffer by
// element id.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 B;
layout(location = 3) in uint element;

uniform mat4 clipFromWorld;

out vec3 vPosition;  // world space, perspective-correct
out vec3 vB;         // Gouraud, where the polygon method does not apply
flat out uint vElement;

void main() {
  gl_Position = clipFromWorld * vec4(position, 1.0);
  vPosition = position;
  vB = B;
  vElement = element;
}
