#version 450 core
#include "lib/bezier.glsl"
#include "lib/c1_pieces.glsl"
// The one-pass C1 evaluation (c1_forward.vert): the value at this fragment's surface point.
in vec3 vLambda;
#if DEGREE == 3
in vec3 vUU, vVV, vWW, vUW;
flat in vec3 vAlpha, vBeta;
#else
in vec3 vSumU, vSumV, vSumW;
flat in vec3 vE0, vE1, vE2, vZeta, vSplit;
#endif

layout(location = 0) out vec4 radiosity;

void main() {
#if DEGREE == 3
  radiosity = vec4(cubicFromSums(vLambda, vUU, vVV, vWW, vUW) + cloughTocherCorrection(vLambda, vAlpha, vBeta), 1.0);
#else
  radiosity = vec4(quadraticFromSums(vLambda, vSumU, vSumV, vSumW) + powellSabinRest(vLambda, vE0, vE1, vE2, vZeta, vSplit), 1.0);
#endif
}
