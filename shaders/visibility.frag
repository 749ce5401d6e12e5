#version 450 core
// What the pixel sees: its triangle + 1 (0 is background) and the barycentric coordinates of
// its surface point, bit for bit.
in vec3 vLambda;
flat in uint vTriangle;

layout(location = 0) out uvec4 visible;

void main() { visible = uvec4(vTriangle + 1u, floatBitsToUint(vLambda)); }
