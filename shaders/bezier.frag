#version 450 core
#include "lib/bezier.glsl"
#include "lib/pixel_centre.glsl"
// The exact value of the piece at this pixel centre's surface point: the accuracy ceiling of the
// GPU path (no tessellation). Linear radiosity, like mesh.frag. DEGREE is defined by the
// program (lib/bezier.glsl).
in vec3 vBeta;
in vec4 vClip;
flat in vec4 vControl[8];

layout(location = 0) out vec4 radiosity;

void main() { radiosity = vec4(bezierTriangle(vControl, AT_PIXEL_CENTRE(vBeta, pixelCentreStep(vClip))), 1.0); }
