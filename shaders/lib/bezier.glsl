// Triangular Bezier patches of degree 2 or 3 (C&W eq. 9.7), the GLSL twin of
// renderer/interp/bezier_triangle.h:
//   B(beta) = sum_{i+j+k=n} n!/(i! j! k!) beta_u^i beta_v^j beta_w^k b_ijk,
// control values b_ijk in the same order (descending i, then descending j), RGB stored three
// floats each into vec4s.
float powInt(float x, int e) {
  float r = 1.0;  // pow(0, 0) is undefined in GLSL; here it is 1, as the formula needs
  for (int q = 0; q < e; ++q) r *= x;
  return r;
}

float factorial(int n) { return n <= 1 ? 1.0 : (n == 2 ? 2.0 : 6.0); }

vec3 bezierControl(vec4 net[8], int index) {
  int f = 3 * index;
  return vec3(net[f / 4][f % 4], net[(f + 1) / 4][(f + 1) % 4], net[(f + 2) / 4][(f + 2) % 4]);
}

vec3 bezierTriangle(int n, vec4 net[8], vec3 beta) {
  vec3 B = vec3(0.0);
  int index = 0;
  for (int i = n; i >= 0; --i)
    for (int j = n - i; j >= 0; --j) {
      int k = n - i - j;
      float weight = factorial(n) / (factorial(i) * factorial(j) * factorial(k)) * powInt(beta.x, i) *
                     powInt(beta.y, j) * powInt(beta.z, k);
      B += weight * bezierControl(net, index++);
    }
  return B;
}
