// The element polygons of the polygon pass (MeshRenderer::uploadPolygons), std430: per corner
// its world position, B, and for serendipity quads the B of the mid-edge node after it;
// element e's corners are firstCorner[e] .. firstCorner[e + 1] - 1.
struct PolygonCorner {
  vec4 position;  // world, w unused
  vec4 B;
  vec4 midB;
};
layout(std430, binding = 0) readonly buffer Corners { PolygonCorner corners[]; };
layout(std430, binding = 1) readonly buffer Offsets { uint firstCorner[]; };  // elements + 1 entries

// Clip coordinates to window coordinates, as the rasteriser places them.
vec2 windowOf(vec4 clip, vec2 viewportSize) { return (clip.xy / clip.w * 0.5 + 0.5) * viewportSize; }

// A triangle or quad element's corners (count 3 or 4; a triangle's fourth is its third), the
// elements a mesh mostly has, so that the shaders can hold them with constant indices; 0 for
// other polygons, the arrays then unset.
int smallPolygon(uint element, out vec3 world[4], out vec3 values[4]) {
  uint first = firstCorner[element];
  int count = int(firstCorner[element + 1u] - first);
  if (count != 3 && count != 4) return 0;
  for (int i = 0; i < 4; ++i) {
    uint corner = first + uint(min(i, count - 1));
    world[i] = corners[corner].position.xyz;
    values[i] = corners[corner].B.rgb;
  }
  return count;
}
