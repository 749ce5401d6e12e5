#version 450 core
#include "lib/pixel_centre.glsl"
#include "lib/polygon_corners.glsl"
#include "lib/scanline_gouraud.glsl"
// Scanline Gouraud (fig. 9.7), bilinear quads and 8-node serendipity quads per pixel, from the
// element's polygon. MODE, defined by the program, picks one (a compile-time choice: llvmpipe
// pays for both sides of a branch on a uniform). LARGE_POLYGONS (scanline only) is 1 where the
// mesh has elements of more than four corners: the loop over any polygon's edges, with its
// arrays in memory, costs llvmpipe about one Gouraud frame even where no pixel takes it.
#define MODE_SCANLINE 0
#define MODE_BILINEAR 1
#define MODE_SERENDIPITY 2

uniform mat4 clipFromWorld;

in vec3 vPosition;
in vec4 vClip;
in vec3 vB;
flat in uint vElement;
#if CORNERS_PER_VERTEX
flat in int vCount;  // 3 or 4: the polygon is in the flat inputs (polygon.vert)
flat in vec3 vCornerB[4];
#if MODE == MODE_SCANLINE
flat in vec2 vScreen[4];
flat in int vFront;
#else
flat in vec3 vCorner[4];
#endif
#endif

layout(location = 0) out vec4 radiosity;

vec3 surfacePoint;  // this pixel centre's (lib/pixel_centre.glsl), set first in main
vec3 gouraudB;      // vB, at the pixel centre where the method is per pixel; set first in main

#if MODE == MODE_SCANLINE && LARGE_POLYGONS
// Scanline Gouraud at this pixel centre, on the polygon projected as the rasteriser sees it.
// Elements with corners behind the eye, or more corners than the shader holds, fall back to
// Gouraud on their triangles.
vec3 scanline(uint first, int count) {
  if (count > MAX_POLYGON_CORNERS) return gouraudB;
  vec2 screen[MAX_POLYGON_CORNERS];
  vec3 values[MAX_POLYGON_CORNERS];
  for (int i = 0; i < count; ++i) {
    vec4 clip = clipFromWorld * vec4(cornerPosition(first + uint(i)), 1.0);
    if (clip.w <= 0.0) return gouraudB;
    screen[i] = windowOf(clip, viewportSize);
    values[i] = cornerB(first + uint(i));
  }
  vec3 B;
  return scanlineGouraud(count, screen, values, gl_FragCoord.xy, B) ? B : gouraudB;
}
#endif

// The quad's own parameters (s, t) at this pixel: Newton's method for the (s, t) whose point
// x(s, t) is nearest this pixel centre's surface point, as renderer/interp/bilinear_map.cpp does.
vec2 quadParameters(vec3 p0, vec3 p1, vec3 p2, vec3 p3) {
  // A parallelogram's map is affine: the first step lands on the answer.
  vec3 twist = p0 - p1 + p2 - p3;
  bool affine = dot(twist, twist) <= 1e-12 * (dot(p1 - p0, p1 - p0) + dot(p3 - p0, p3 - p0));
  vec2 st = vec2(0.5);
  for (int iteration = 0; iteration < 8; ++iteration) {
    vec3 x = mix(mix(p0, p1, st.x), mix(p3, p2, st.x), st.y);
    vec3 r = x - surfacePoint;
    vec3 a = mix(p1 - p0, p2 - p3, st.y), b = mix(p3 - p0, p2 - p1, st.x);
    float aa = dot(a, a), ab = dot(a, b), bb = dot(b, b);
    float det = aa * bb - ab * ab;
    if (!(det > 0.0)) break;
    float ra = dot(r, a), rb = dot(r, b);
    vec2 step = vec2(bb * ra - ab * rb, aa * rb - ab * ra) / det;
    st -= step;
    // Converged: Newton's error after a step of 1e-5 is of order 1e-10 (a parallelogram's is
    // exact after one step), below float's precision. bilinear_map.cpp stops likewise, at
    // double's.
    if (affine || !(abs(step.x) + abs(step.y) > 1e-5)) break;
  }
  return st;
}

// The 8-node serendipity quad (C&W §9.2's quadratic elements) on (xi, eta) = 2 (s, t) - 1, the
// GLSL twin of the quad in renderer/interp/quadratic_lagrange.cpp.
vec3 serendipity(uint first) {
  vec2 q = 2.0 * quadParameters(cornerPosition(first), cornerPosition(first + 1u),
                                 cornerPosition(first + 2u), cornerPosition(first + 3u)) -
           1.0;
  float xi = q.x, eta = q.y;
  const vec2 corner[4] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, 1));
  vec3 B = vec3(0.0);
  for (int i = 0; i < 4; ++i) {
    float a = corner[i].x, b = corner[i].y;
    B += 0.25 * (1.0 + xi * a) * (1.0 + eta * b) * (xi * a + eta * b - 1.0) * cornerB(first + uint(i));
  }
  vec3 m0 = cornerMidB(first), m1 = cornerMidB(first + 1u);  // eta = -1, xi = +1
  vec3 m2 = cornerMidB(first + 2u), m3 = cornerMidB(first + 3u);  // eta = +1, xi = -1
  return B + 0.5 * (1.0 - xi * xi) * ((1.0 - eta) * m0 + (1.0 + eta) * m2) +
         0.5 * (1.0 - eta * eta) * ((1.0 + xi) * m1 + (1.0 - xi) * m3);
}

// Scanline Gouraud, or bilinear on a quad, where the element is a triangle or a quad; false
// for larger polygons. Its corners come from polygon.vert's flat outputs or are read here
// (CORNERS_PER_VERTEX: MeshRenderer::drawPolygons picks whichever reads fewer).
bool smallPolygonValue(out vec3 B) {
#if CORNERS_PER_VERTEX
  int count = vCount;
  vec3 values[4] = vCornerB;
#if MODE == MODE_SCANLINE
  vec2 screen[4] = vScreen;
  bool front = vFront != 0;
#else
  vec3 world[4] = vCorner;
#endif
#else
  vec3 world[4], values[4];
  int count = smallPolygon(vElement, world, values);
#if MODE == MODE_SCANLINE
  vec2 screen[4];
  bool front = true;
  for (int i = 0; i < 4; ++i) {
    vec4 clip = clipFromWorld * vec4(world[i], 1.0);
    screen[i] = windowOf(clip, viewportSize);
    front = front && clip.w > 0.0;
  }
#endif
#endif
  B = gouraudB;
  if (count == 0) return false;
#if MODE == MODE_SCANLINE
  vec3 scanned;
  if (front && scanlineGouraud4(count, screen, values, gl_FragCoord.xy, scanned)) B = scanned;
#else
  if (count == 4) {
    vec2 st = quadParameters(world[0], world[1], world[2], world[3]);
    B = mix(mix(values[0], values[1], st.x), mix(values[3], values[2], st.x), st.y);
  }
#endif
  return true;
}

void main() {
  gouraudB = vB;
#if MODE != MODE_SCANLINE
  vec2 step = pixelCentreStep(vClip);
  surfacePoint = AT_PIXEL_CENTRE(vPosition, step);
  gouraudB = AT_PIXEL_CENTRE(vB, step);  // a triangle's bilinear value is its linear one
#endif
  vec3 B = gouraudB;
#if MODE == MODE_SERENDIPITY
  B = serendipity(firstCorner(vElement));
#else
  if (!smallPolygonValue(B)) {
#if MODE == MODE_SCANLINE && LARGE_POLYGONS
    uint first = firstCorner(vElement);
    B = scanline(first, int(firstCorner(vElement + 1u) - first));
#endif
  }
#endif
  radiosity = vec4(B, 1.0);
}
