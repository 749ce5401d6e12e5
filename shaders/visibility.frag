#version 450 core
#include "lib/pixel_centre.glsl"
// What the pixel sees, into the target's own colour (renderer/gl/deferred_pass.h): its
// triangle + 1 (0, as the target is cleared, is background), exact as a float below 2^24, and
// the barycentric coordinates of its pixel centre's surface point.
in vec3 vLambda;
in vec4 vClip;
flat in uint vTriangle;

layout(location = 0) out vec4 visible;

void main() {
  vec2 step = pixelCentreStep(vClip);
  visible = vec4(float(vTriangle + 1u), AT_PIXEL_CENTRE(vLambda, step));
}
