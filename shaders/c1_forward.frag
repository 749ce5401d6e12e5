#version 450 core
#include "lib/bezier.glsl"
#include "lib/c1_pieces.glsl"
// The one-pass C1 evaluation (c1_forward.vert): the value at this fragment's surface point.
in vec3 vLambda;
flat in vec4 vNet[NET_VEC4S];

layout(location = 0) out vec4 radiosity;

void main() { radiosity = vec4(c1Value(vNet, vLambda), 1.0); }
