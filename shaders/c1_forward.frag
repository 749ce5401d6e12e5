#version 450 core
#include "lib/bezier.glsl"
#include "lib/c1_pieces.glsl"
// The one-pass C1 evaluation (c1_forward.vert): the value at this fragment's surface point.
in vec3 vLambda;
#if DEGREE == 3
in vec3 vUU, vVV, vWW, vUW;
flat in vec3 vAlpha, vBeta;
#else
flat in vec4 vNet[NET_VEC4S];
#endif

layout(location = 0) out vec4 radiosity;

void main() {
#if DEGREE == 3
  radiosity = vec4(cubicFromSums(vLambda, vUU, vVV, vWW, vUW) + cloughTocherCorrection(vLambda, vAlpha, vBeta), 1.0);
#else
  radiosity = vec4(c1Value(vNet, vLambda), 1.0);
#endif
}
