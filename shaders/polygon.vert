#version 450 core
#include "lib/polygon_corners.glsl"
#include "lib/eye_plane.glsl"
// The element triangles (as for Gouraud), for the methods that need the whole element polygon
// per pixel: scanline Gouraud, bilinear and serendipity quads (MODE, as polygon.frag).
#define MODE_SCANLINE 0
#define MODE_BILINEAR 1
#define MODE_SERENDIPITY 2
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 B;
layout(location = 3) in uint element;

uniform mat4 clipFromWorld;
uniform vec2 viewportSize;

out vec3 vPosition;  // world space, perspective-correct
out vec4 vClip;      // its clip position (lib/pixel_centre.glsl)
out vec3 vB;         // Gouraud, where the polygon method does not apply
flat out uint vElement;
#if CORNERS_PER_VERTEX
// A triangle or quad element's corners as flat outputs (smallPolygon; vCount 0 for larger
// polygons, which polygon.frag reads itself): read once per vertex rather than per pixel.
flat out int vCount;
flat out vec3 vCornerB[4];
#if MODE == MODE_SCANLINE
flat out vec2 vScreen[4];  // window coordinates
flat out int vFront;       // 1 when every corner is in front of the eye
#else
flat out vec3 vCorner[4];  // world
#endif
#endif

void main() {
  gl_Position = clipFromWorld * vec4(position, 1.0);
  clipBehindTheEye();
  vPosition = position;
  vClip = gl_Position;
  vB = B;
  vElement = element;
#if CORNERS_PER_VERTEX
  vec3 world[4];
  vCount = smallPolygon(element, world, vCornerB);
#if MODE == MODE_SCANLINE
  vFront = 1;
  for (int i = 0; i < 4; ++i) {
    vec4 clip = clipFromWorld * vec4(world[i], 1.0);
    vScreen[i] = windowOf(clip, viewportSize);
    if (!(clip.w > 0.0)) vFront = 0;
  }
#else
  vCorner = world;
#endif
#endif
}
