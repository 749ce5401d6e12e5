#version 450 core
#include "lib/scanline_gouraud.glsl"
// Scanline Gouraud (fig. 9.7), bilinear quads and 8-node serendipity quads per pixel, from the
// element's polygon. MODE, defined by the program, picks one (a compile-time choice: llvmpipe
// pays for both sides of a branch on a uniform).
#define MODE_SCANLINE 0
#define MODE_BILINEAR 1
#define MODE_SERENDIPITY 2

struct PolygonCorner {
  vec4 position;  // world, w unused
  vec4 B;
  vec4 midB;  // serendipity quads: B of the mid-edge node after this corner
};
layout(std430, binding = 0) readonly buffer Corners { PolygonCorner corners[]; };
layout(std430, binding = 1) readonly buffer Offsets { uint firstCorner[]; };  // elements + 1 entries

uniform mat4 clipFromWorld;
uniform vec2 viewportSize;

in vec3 vPosition;
in vec3 vB;
flat in uint vElement;

layout(location = 0) out vec4 radiosity;

// Scanline Gouraud at this pixel centre, on the polygon projected as the rasteriser sees it.
// Elements with corners behind the eye, or more corners than the shader holds, fall back to
// Gouraud on their triangles.
vec3 scanline(uint first, int count) {
  if (count > MAX_POLYGON_CORNERS) return vB;
  vec2 screen[MAX_POLYGON_CORNERS];
  vec3 values[MAX_POLYGON_CORNERS];
  for (int i = 0; i < count; ++i) {
    vec4 clip = clipFromWorld * vec4(corners[first + uint(i)].position.xyz, 1.0);
    if (clip.w <= 0.0) return vB;
    screen[i] = (clip.xy / clip.w * 0.5 + 0.5) * viewportSize;
    values[i] = corners[first + uint(i)].B.rgb;
  }
  vec3 B;
  return scanlineGouraud(count, screen, values, gl_FragCoord.xy, B) ? B : vB;
}

// The quad's own parameters (s, t) at this pixel: Newton's method for the (s, t) whose point
// x(s, t) is nearest this pixel's surface point, as renderer/interp/bilinear_map.cpp does.
vec2 quadParameters(uint first) {
  vec3 p0 = corners[first].position.xyz, p1 = corners[first + 1u].position.xyz;
  vec3 p2 = corners[first + 2u].position.xyz, p3 = corners[first + 3u].position.xyz;
  vec2 st = vec2(0.5);
  for (int iteration = 0; iteration < 8; ++iteration) {
    vec3 x = mix(mix(p0, p1, st.x), mix(p3, p2, st.x), st.y);
    vec3 r = x - vPosition;
    vec3 a = mix(p1 - p0, p2 - p3, st.y), b = mix(p3 - p0, p2 - p1, st.x);
    float aa = dot(a, a), ab = dot(a, b), bb = dot(b, b);
    float det = aa * bb - ab * ab;
    if (!(det > 0.0)) break;
    float ra = dot(r, a), rb = dot(r, b);
    st -= vec2(bb * ra - ab * rb, aa * rb - ab * ra) / det;
  }
  return st;
}

vec3 bilinear(uint first) {
  vec2 st = quadParameters(first);
  vec3 f0 = corners[first].B.rgb, f1 = corners[first + 1u].B.rgb, f2 = corners[first + 2u].B.rgb,
       f3 = corners[first + 3u].B.rgb;
  return mix(mix(f0, f1, st.x), mix(f3, f2, st.x), st.y);
}

// The 8-node serendipity quad (C&W §9.2's quadratic elements) on (xi, eta) = 2 (s, t) - 1, the
// GLSL twin of the quad in renderer/interp/quadratic_lagrange.cpp.
vec3 serendipity(uint first) {
  vec2 q = 2.0 * quadParameters(first) - 1.0;
  float xi = q.x, eta = q.y;
  const vec2 corner[4] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, 1));
  vec3 B = vec3(0.0);
  for (int i = 0; i < 4; ++i) {
    float a = corner[i].x, b = corner[i].y;
    B += 0.25 * (1.0 + xi * a) * (1.0 + eta * b) * (xi * a + eta * b - 1.0) * corners[first + uint(i)].B.rgb;
  }
  vec3 m0 = corners[first].midB.rgb, m1 = corners[first + 1u].midB.rgb;  // eta = -1, xi = +1
  vec3 m2 = corners[first + 2u].midB.rgb, m3 = corners[first + 3u].midB.rgb;  // eta = +1, xi = -1
  return B + 0.5 * (1.0 - xi * xi) * ((1.0 - eta) * m0 + (1.0 + eta) * m2) +
         0.5 * (1.0 - eta * eta) * ((1.0 + xi) * m1 + (1.0 - xi) * m3);
}

void main() {
  uint first = firstCorner[vElement];
  int count = int(firstCorner[vElement + 1u] - first);
  vec3 B = vB;
#if MODE == MODE_SCANLINE
  B = scanline(first, count);
#elif MODE == MODE_SERENDIPITY
  B = serendipity(first);
#else
  if (count == 4) B = bilinear(first);
#endif
  radiosity = vec4(B, 1.0);
}
