// The element polygons of the polygon pass (MeshRenderer::uploadPolygons), read as buffer
// textures (on llvmpipe a texel fetch costs less than a storage-buffer load): per corner three
// texels, its world position, B, and for serendipity quads the B of the mid-edge node after it;
// element e's corners are firstCorner(e) .. firstCorner(e + 1) - 1.
layout(binding = 2) uniform samplerBuffer cornerTexels;
layout(binding = 3) uniform usamplerBuffer firstCornerTexels;  // elements + 1 entries

uint firstCorner(uint element) { return texelFetch(firstCornerTexels, int(element)).x; }
vec3 cornerPosition(uint corner) { return texelFetch(cornerTexels, 3 * int(corner)).xyz; }
vec3 cornerB(uint corner) { return texelFetch(cornerTexels, 3 * int(corner) + 1).rgb; }
vec3 cornerMidB(uint corner) { return texelFetch(cornerTexels, 3 * int(corner) + 2).rgb; }

// Clip coordinates to window coordinates, as the rasteriser places them.
vec2 windowOf(vec4 clip, vec2 viewportSize) { return (clip.xy / clip.w * 0.5 + 0.5) * viewportSize; }

// A triangle or quad element's corners (count 3 or 4; a triangle's fourth is its third), the
// elements a mesh mostly has, so that the shaders can hold them with constant indices; 0 for
// other polygons, the arrays then unset.
int smallPolygon(uint element, out vec3 world[4], out vec3 values[4]) {
  uint first = firstCorner(element);
  int count = int(firstCorner(element + 1u) - first);
  if (count != 3 && count != 4) return 0;
  for (int i = 0; i < 4; ++i) {
    uint corner = first + uint(min(i, count - 1));
    world[i] = cornerPosition(corner);
    values[i] = cornerB(corner);
  }
  return count;
}
