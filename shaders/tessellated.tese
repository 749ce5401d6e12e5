#version 450 core
#include "lib/bezier.glsl"
// Evaluates the piece at each vertex the tessellator generates (gl_TessCoord is barycentric
// in the patch's three corners, as the net's b_ijk are); the rasteriser then interpolates
// linearly between them (C&W §9.2: smaller polygons passed to the hardware for linear
// interpolation).
layout(triangles, equal_spacing, ccw) in;

uniform mat4 clipFromWorld;
uniform int degree;

in vec3 tcPosition[];
patch in vec4 pControl[8];
out vec3 teB;

void main() {
  vec3 beta = gl_TessCoord;
  vec3 position = beta.x * tcPosition[0] + beta.y * tcPosition[1] + beta.z * tcPosition[2];
  gl_Position = clipFromWorld * vec4(position, 1.0);
  teB = bezierTriangle(degree, pControl, beta);
}
