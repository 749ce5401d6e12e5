#version 450 core
#include "lib/tonemap.glsl"
// Linear radiosity -> display colour. Alpha 0 marks pixels where no surface was drawn.
uniform sampler2D linearRadiosity;
uniform float exposureScale;
uniform vec3 background;

layout(location = 0) out vec4 display;

void main() {
  vec4 B = texelFetch(linearRadiosity, ivec2(gl_FragCoord.xy), 0);
  bool finite = !any(isnan(B.rgb)) && !any(isinf(B.rgb));
  display = vec4(B.a > 0.0 && finite ? toneMap(B.rgb, exposureScale) : background, 1.0);
}
