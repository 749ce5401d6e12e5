#version 450 core
// What the pixel sees, into the target's own colour (renderer/gl/deferred_pass.h): its
// triangle + 1 (0, as the target is cleared, is background), exact as a float below 2^24, and
// the barycentric coordinates of its surface point, bit for bit.
in vec3 vLambda;
flat in uint vTriangle;

layout(location = 0) out vec4 visible;

void main() { visible = vec4(float(vTriangle + 1u), vLambda); }
