#version 450 core
// Linear interpolation between the generated vertices (perspective-correct), or, drawn again
// as lines over the display, the generated triangles themselves (the tessellation overlay).
uniform bool wireframe;
uniform vec4 wireColor;
in vec3 teB;
layout(location = 0) out vec4 radiosity;
void main() { radiosity = wireframe ? wireColor : vec4(teB, 1.0); }
