#version 450 core
uniform vec4 color;
layout(location = 0) out vec4 display;
void main() { display = color; }
