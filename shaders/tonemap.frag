#version 450 core
#include "lib/tonemap.glsl"
// Linear radiosity -> display colour. Alpha is coverage: 0 where no surface was drawn, 1 where
// the mesh was, a fraction in a final gather's antialiased pixels (a shown image), which blend
// with the background by it as `radview render --method final-gather` blends them.
uniform sampler2D linearRadiosity;
uniform float exposureScale;
uniform vec3 background;

layout(location = 0) out vec4 display;

void main() {
  vec4 B = texelFetch(linearRadiosity, ivec2(gl_FragCoord.xy), 0);
  bool finite = !any(isnan(B.rgb)) && !any(isinf(B.rgb));
  float coverage = finite ? clamp(B.a, 0.0, 1.0) : 0.0;
  display = vec4(coverage > 0.0 ? mix(background, toneMap(B.rgb, exposureScale), coverage) : background, 1.0);
}
