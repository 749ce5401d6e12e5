#version 450 core
in vec4 vColor;
layout(location = 0) out vec4 display;
void main() { display = vColor; }
