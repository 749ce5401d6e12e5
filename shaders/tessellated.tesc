#version 450 core
#include "lib/bezier.glsl"
#include "lib/tessellation_level.glsl"
// Chooses the tessellation level: fixed, or adaptive (the smallest whose display error stays
// under the tolerance, lib/tessellation_level.glsl). The control values travel as a `patch
// out` taken from the first vertex, so nothing indexes by gl_PrimitiveID (wrong on llvmpipe
// past ~1365 patches per draw, ../shared/PLATFORM.md).
layout(vertices = 3) out;

uniform int degree;
uniform int fixedLevel;  // 1..64; 0 for adaptive
uniform float exposureScale;
uniform float tolerance;  // display units, e.g. 0.5 / 255

in vec3 vPosition[];
in vec4 vControl[][8];
out vec3 tcPosition[];
patch out vec4 pControl[8];

void main() {
  tcPosition[gl_InvocationID] = vPosition[gl_InvocationID];
  if (gl_InvocationID == 0) {
    pControl = vControl[0];
    if (fixedLevel > 0) {
      float L = float(fixedLevel);
      gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = L;
      gl_TessLevelInner[0] = L;
    } else {
      vec3 outer;
      gl_TessLevelInner[0] = adaptiveLevels(degree, vControl[0], exposureScale, tolerance, outer);
      gl_TessLevelOuter[0] = outer.x;
      gl_TessLevelOuter[1] = outer.y;
      gl_TessLevelOuter[2] = outer.z;
    }
  }
}
