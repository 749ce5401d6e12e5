#version 450 core
// Linear interpolation between the generated vertices (perspective-correct).
in vec3 teB;
layout(location = 0) out vec4 radiosity;
void main() { radiosity = vec4(teB, 1.0); }
