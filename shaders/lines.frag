#version 450 core
uniform vec4 colour;
layout(location = 0) out vec4 display;
void main() { display = colour; }
