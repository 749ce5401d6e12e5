#version 450 core
#include "lib/bezier.glsl"
#include "lib/eye_plane.glsl"
// Evaluates the piece at each vertex the tessellator generates (gl_TessCoord is barycentric
// in the patch's three corners, as the net's b_ijk are); the rasteriser then interpolates
// linearly between them (C&W §9.2: smaller polygons passed to the hardware for linear
// interpolation). With heightScale > 0, the radiosity surface of fig. 9.13: each point is
// lifted off its element along the element's normal by heightScale times its luminance.
layout(triangles, equal_spacing, ccw) in;

uniform mat4 clipFromWorld;
uniform float heightScale;

in vec3 tcPosition[];
patch in vec4 pControl[8];
out vec3 teB;
out vec3 teWorld;

void main() {
  vec3 beta = gl_TessCoord;
  vec3 position = beta.x * tcPosition[0] + beta.y * tcPosition[1] + beta.z * tcPosition[2];
  teB = bezierTriangle(pControl, beta);
  if (heightScale > 0.0) {
    vec3 n = normalize(cross(tcPosition[1] - tcPosition[0], tcPosition[2] - tcPosition[0]));
    position += n * heightScale * dot(teB, vec3(0.2126, 0.7152, 0.0722));
  }
  teWorld = position;
  gl_Position = clipFromWorld * vec4(position, 1.0);
  clipBehindTheEye();
}
