#version 450 core
#include "lib/bezier.glsl"
#include "lib/c1_pieces.glsl"
// The deferred per-pixel pass's evaluation (renderer/gl/deferred_pass.h): once per covered
// pixel, whatever the depth complexity, the value of the piece of its triangle that holds its
// surface point, from the packed values in a buffer texture.
layout(binding = 0) uniform sampler2D visibility;  // the visibility pass's (triangle + 1, lambda)
layout(binding = 1) uniform samplerBuffer nets;

layout(location = 0) out vec4 radiosity;

void main() {
  vec4 seen = texelFetch(visibility, ivec2(gl_FragCoord.xy), 0);
  // The background keeps its texel: written back rather than discarded, as a discard before
  // the fetches of the values slows llvmpipe's C1 frames (radview_scale_bench shows it).
  bool background = seen.x == 0.0;
  int first = max(int(seen.x) - 1, 0) * NET_VEC4S;
  vec4 n[NET_VEC4S];
  for (int i = 0; i < NET_VEC4S; ++i) n[i] = texelFetch(nets, first + i);
  radiosity = background ? seen : vec4(c1Value(n, seen.yzw), 1.0);
}
