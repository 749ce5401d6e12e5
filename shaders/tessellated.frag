#version 450 core
// Linear interpolation between the generated vertices (perspective-correct), or, drawn again
// as lines over the display, the generated triangles themselves (the tessellation overlay).
// On the radiosity surface (fig. 9.13) the value is shaded by the surface's slope towards the
// eye, so its shape reads.
uniform bool wireframe;
uniform vec4 wireColour;
uniform bool shadeSurface;
uniform vec3 eye;
in vec3 teB;
in vec3 teWorld;
layout(location = 0) out vec4 radiosity;
void main() {
  if (wireframe) {
    radiosity = wireColour;
    return;
  }
  float shade = 1.0;
  if (shadeSurface) {
    vec3 n = normalize(cross(dFdx(teWorld), dFdy(teWorld)));
    shade = 0.35 + 0.65 * abs(dot(n, normalize(eye - teWorld)));
  }
  radiosity = vec4(teB * shade, 1.0);
}
