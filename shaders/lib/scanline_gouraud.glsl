// Gouraud shading as scanline hardware computed it (C&W §9.2, fig. 9.7): down the two edges
// spanning the pixel's scanline, then across the span. The GLSL twin of
// renderer/interp/scanline_gouraud.cpp, on a polygon already projected to window coordinates:
// crossings of edges with y0 <= y < y1 (half-open, a vertex counts once), sorted by x, spans
// between successive pairs (even-odd).
const int MAX_POLYGON_CORNERS = 32;

bool scanlineGouraud(int count, vec2 screen[MAX_POLYGON_CORNERS], vec3 values[MAX_POLYGON_CORNERS], vec2 p,
                     out vec3 B) {
  float crossingX[MAX_POLYGON_CORNERS];
  vec3 crossingB[MAX_POLYGON_CORNERS];
  int crossings = 0;
  for (int i = 0; i < count; ++i) {
    int j = (i + 1) % count;
    int lo = screen[i].y <= screen[j].y ? i : j;
    int hi = lo == i ? j : i;
    float y0 = screen[lo].y, y1 = screen[hi].y;
    if (!(y0 <= p.y && p.y < y1)) continue;
    float t = (p.y - y0) / (y1 - y0);
    // Insertion by x keeps the crossings sorted.
    float x = mix(screen[lo].x, screen[hi].x, t);
    vec3 value = mix(values[lo], values[hi], t);
    int at = crossings++;
    while (at > 0 && crossingX[at - 1] > x) {
      crossingX[at] = crossingX[at - 1];
      crossingB[at] = crossingB[at - 1];
      --at;
    }
    crossingX[at] = x;
    crossingB[at] = value;
  }
  for (int k = 0; k + 1 < crossings; k += 2) {
    if (p.x < crossingX[k] || p.x > crossingX[k + 1]) continue;
    float width = crossingX[k + 1] - crossingX[k];
    B = mix(crossingB[k], crossingB[k + 1], width > 0.0 ? (p.x - crossingX[k]) / width : 0.5);
    return true;
  }
  return false;
}
