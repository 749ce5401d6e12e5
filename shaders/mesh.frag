#version 450 core
// Writes linear radiosity; tone mapping happens in a later pass so the linear values can be
// read back and compared with the CPU reference.
const int METHOD_FLAT = 0;
const int METHOD_GOURAUD = 1;

uniform int method;
uniform bool perspectiveCorrect;

in vec3 vB;
in vec4 vBw;
flat in vec3 vBFlat;

layout(location = 0) out vec4 radiosity;

void main() {
  vec3 B = method == METHOD_FLAT ? vBFlat : (perspectiveCorrect ? vB : vBw.rgb / vBw.w);
  radiosity = vec4(B, 1.0);
}
