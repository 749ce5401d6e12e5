#version 450 core
in vec4 vColour;
layout(location = 0) out vec4 display;
void main() { display = vColour; }
