#version 450 core
// Passes the piece's control values on as a `patch out` taken from the first vertex, so
// nothing indexes by gl_PrimitiveID (wrong on llvmpipe past ~1365 patches per draw, renderer/gl/README.md,
// "Platform notes"), and sets the levels the CPU chose: the same for the pieces on both
// sides of every shared edge, so no crack opens between them.
layout(vertices = 3) out;

in vec3 vPosition[];
in vec4 vControl[][8];
in vec4 vLevels[];
out vec3 tcPosition[];
patch out vec4 pControl[8];

void main() {
  tcPosition[gl_InvocationID] = vPosition[gl_InvocationID];
  if (gl_InvocationID == 0) {
    pControl = vControl[0];
    gl_TessLevelOuter[0] = vLevels[0].x;
    gl_TessLevelOuter[1] = vLevels[0].y;
    gl_TessLevelOuter[2] = vLevels[0].z;
    gl_TessLevelInner[0] = vLevels[0].w;
  }
}
