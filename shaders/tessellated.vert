#version 450 core
// A Bezier piece of the quadratic or C1 methods as a 3-vertex patch (renderer/gl/
// patch_vertices.h), with its tessellation levels computed on the CPU
// (renderer/interp/tessellation_level.h): outer levels in xyz, inner in w.
layout(location = 0) in vec3 position;
layout(location = 2) in vec4 control[8];
layout(location = 10) in vec4 levels;
out vec3 vPosition;
out vec4 vControl[8];
out vec4 vLevels;
void main() {
  vPosition = position;
  vControl = control;
  vLevels = levels;
}
