// The adaptive tessellation level of a Bezier piece: the GLSL twin of
// renderer/interp/tessellation_level.cpp, which derives the bound. Needs lib/bezier.glsl.
const int MAX_TESSELLATION_LEVEL = 64;

float srgbSlope(float v) {
  v = max(v, 0.0);
  return v <= 0.0031308 ? 12.92 : (1.055 / 2.4) * pow(v, -7.0 / 12.0);
}

float levelFor(float constant, float M, float darkest, float exposureScale, float tolerance) {
  if (exposureScale * darkest >= 1.0) return 1.0;
  float displayError = constant * M * exposureScale * srgbSlope(exposureScale * darkest);
  return clamp(ceil(sqrt(displayError / tolerance)), 1.0, float(MAX_TESSELLATION_LEVEL));
}

int netIndex(int n, int i, int j) { return (n - i) * (n - i + 1) / 2 + (n - i - j); }

float largestComponent(vec3 v) { return max(abs(v.r), max(abs(v.g), abs(v.b))); }

// outer[c]: the edge opposite corner c; returns the inner level.
float adaptiveLevels(int n, vec4 net[8], float exposureScale, float tolerance, out vec3 outer) {
  outer = vec3(1.0);
  if (n < 2) return 1.0;
  float order = float(n * (n - 1));
  float M = 0.0, darkest = 1e30;
  vec3 edgeM = vec3(0.0), edgeDarkest = vec3(1e30);
  for (int i = n; i >= 0; --i)
    for (int j = n - i; j >= 0; --j) {
      int k = n - i - j;
      vec3 b = bezierControl(net, netIndex(n, i, j));
      float low = min(b.r, min(b.g, b.b));
      darkest = min(darkest, low);
      if (i == 0) edgeDarkest.x = min(edgeDarkest.x, low);
      if (j == 0) edgeDarkest.y = min(edgeDarkest.y, low);
      if (k == 0) edgeDarkest.z = min(edgeDarkest.z, low);
    }
  for (int i = n - 2; i >= 0; --i)
    for (int j = n - 2 - i; j >= 0; --j) {
      int k = n - 2 - i - j;
      vec3 ii = bezierControl(net, netIndex(n, i + 2, j));
      vec3 jj = bezierControl(net, netIndex(n, i, j + 2));
      vec3 kk = bezierControl(net, netIndex(n, i, j));
      vec3 ij = bezierControl(net, netIndex(n, i + 1, j + 1));
      vec3 ik = bezierControl(net, netIndex(n, i + 1, j));
      vec3 jk = bezierControl(net, netIndex(n, i, j + 1));
      float dij = largestComponent((ii + jj) - 2.0 * ij);
      float dik = largestComponent((ii + kk) - 2.0 * ik);
      float djk = largestComponent((jj + kk) - 2.0 * jk);
      M = max(M, max(dij, max(dik, djk)));
      if (k == 0) edgeM.z = max(edgeM.z, dij);
      if (j == 0) edgeM.y = max(edgeM.y, dik);
      if (i == 0) edgeM.x = max(edgeM.x, djk);
    }
  for (int c = 0; c < 3; ++c) outer[c] = levelFor(order / 8.0, edgeM[c], edgeDarkest[c], exposureScale, tolerance);
  return levelFor(order / 6.0, M, darkest, exposureScale, tolerance);
}
