#version 450 core
#include "lib/bezier.glsl"
#include "lib/c1_pieces.glsl"
#include "lib/pixel_centre.glsl"
// The one-pass C1 evaluation (c1_forward.vert): the value at this fragment's pixel centre's
// surface point. Every interpolated input is affine on the surface: each is moved there.
in vec3 vLambda;
in vec4 vClip;
#if DEGREE == 3
in vec3 vUU, vVV, vWW, vUW;
flat in vec3 vAlpha, vBeta;
#else
in vec3 vSumU, vSumV, vSumW;
flat in vec3 vE0, vE1, vE2, vZeta, vSplit;
#endif

layout(location = 0) out vec4 radiosity;

void main() {
  vec2 step = pixelCentreStep(vClip);
#if DEGREE == 3
  vec3 lambda = AT_PIXEL_CENTRE(vLambda, step);
  radiosity = vec4(cubicFromSums(lambda, AT_PIXEL_CENTRE(vUU, step), AT_PIXEL_CENTRE(vVV, step), AT_PIXEL_CENTRE(vWW, step),
                                 AT_PIXEL_CENTRE(vUW, step)) +
                       cloughTocherCorrection(lambda, vAlpha, vBeta),
                   1.0);
#else
  vec3 lambda = AT_PIXEL_CENTRE(vLambda, step);
  radiosity = vec4(quadraticFromSums(lambda, AT_PIXEL_CENTRE(vSumU, step), AT_PIXEL_CENTRE(vSumV, step),
                                     AT_PIXEL_CENTRE(vSumW, step)) +
                       powellSabinRest(lambda, vE0, vE1, vE2, vZeta, vSplit),
                   1.0);
#endif
}
