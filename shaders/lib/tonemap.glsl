// Display transform shared by every pass that shows radiosity: exposure in stops, then a
// clamp to [0,1] and the sRGB transfer function. Radiosity is linear in light; the display
// is not.
vec3 toneMap(vec3 B, float exposureScale) {
  vec3 v = clamp(B * exposureScale, 0.0, 1.0);
  vec3 low = v * 12.92;
  vec3 high = 1.055 * pow(v, vec3(1.0 / 2.4)) - 0.055;
  return mix(low, high, step(vec3(0.0031308), v));
}
