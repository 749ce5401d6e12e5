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

// The same for a triangle or a quad (count 3 or 4; screen[3] unused for 3), the elements a mesh
// mostly has, with every index a constant: each edge's crossing, then the four put in order by
// a sorting network. llvmpipe keeps all of it in registers, where the loop above indexes
// arrays in memory and costs several times as much per pixel.
const float kNoCrossing = 3.0e38;

void edgeCrossing(vec2 a, vec3 va, vec2 b, vec3 vb, float y, out float x, out vec3 value) {
  bool aLow = a.y <= b.y;
  vec2 lo = aLow ? a : b, hi = aLow ? b : a;
  float t = (y - lo.y) / (hi.y - lo.y);
  x = lo.y <= y && y < hi.y ? mix(lo.x, hi.x, t) : kNoCrossing;
  value = aLow ? mix(va, vb, t) : mix(vb, va, t);
}

void orderCrossings(inout float xa, inout vec3 va, inout float xb, inout vec3 vb) {
  bool swap = xa > xb;
  float x = xa;
  vec3 v = va;
  xa = swap ? xb : xa;
  va = swap ? vb : va;
  xb = swap ? x : xb;
  vb = swap ? v : vb;
}

bool inSpan(float x0, vec3 v0, float x1, vec3 v1, float px, out vec3 B) {
  float width = x1 - x0;
  B = mix(v0, v1, width > 0.0 ? (px - x0) / width : 0.5);
  return x1 < kNoCrossing && x0 <= px && px <= x1;
}

bool scanlineGouraud4(int count, vec2 screen[4], vec3 values[4], vec2 p, out vec3 B) {
  float x0, x1, x2, x3;
  vec3 v0, v1, v2, v3;
  edgeCrossing(screen[0], values[0], screen[1], values[1], p.y, x0, v0);
  edgeCrossing(screen[1], values[1], screen[2], values[2], p.y, x1, v1);
  bool quad = count == 4;
  edgeCrossing(screen[2], values[2], quad ? screen[3] : screen[0], quad ? values[3] : values[0], p.y, x2, v2);
  edgeCrossing(screen[3], values[3], screen[0], values[0], p.y, x3, v3);
  x3 = quad ? x3 : kNoCrossing;
  orderCrossings(x0, v0, x1, v1);
  orderCrossings(x2, v2, x3, v3);
  orderCrossings(x0, v0, x2, v2);
  orderCrossings(x1, v1, x3, v3);
  orderCrossings(x1, v1, x2, v2);
  vec3 first, second;
  bool inFirst = inSpan(x0, v0, x1, v1, p.x, first), inSecond = inSpan(x2, v2, x3, v3, p.x, second);
  B = inFirst ? first : second;
  return inFirst || inSecond;
}
