#version 450 core
// A Bezier piece of the quadratic or C1 methods as a 3-vertex patch (renderer/gl/
// patch_vertices.h): the tessellator cuts it, the evaluation shader evaluates it.
layout(location = 0) in vec3 position;
layout(location = 2) in vec4 control[8];
out vec3 vPosition;
out vec4 vControl[8];
void main() {
  vPosition = position;
  vControl = control;
}
