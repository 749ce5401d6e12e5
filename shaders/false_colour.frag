#version 450 core
#include "lib/tonemap.glsl"
// Linear radiosity -> false colour, views that make the interpolants' differences visible: the
// value on a colour scale (with a colour bar at the right edge), the magnitude of its
// screen-space gradient (Mach bands, C&W §9.2.2, are jumps in it), and isolines. The plain
// display is a program of its own (tonemap.frag): llvmpipe pays for every branch of a shader,
// taken or not, and one program for both made the plain display 2.5 times as slow.
const int VIEW_VALUE = 1;
const int VIEW_GRADIENT = 2;
const int VIEW_ISOLINES = 3;
const int VIEW_DIFFERENCE = 4;
const int VIEW_STANDARD_ERROR = 5;

uniform sampler2D linearRadiosity;
uniform float exposureScale;
uniform vec3 background;
uniform int view;
uniform float gradientScale;  // gradient view: display value per pixel that maps to the top of the scale
uniform int isolineCount;     // isolines: levels across the display range [0, 1]
// Difference: the comparison, linear radiosity (another method, or a float reference image) or
// display colour (an 8-bit reference image), sampled at this view's relative position; the
// difference in displayed luminance at the ends of the diverging scale.
uniform sampler2D comparisonRadiosity;
uniform bool comparisonLinear;
uniform float differenceScale;
// Standard error: the solution's standard errors of B, linear, drawn as the mesh is (Gouraud), in
// comparisonRadiosity at this view's size; shown as how far B one standard error higher moves
// the displayed luminance, 0 .. differenceScale on the colour scale (noise in what is seen: none
// where the display saturates).

layout(location = 0) out vec4 display;

// Dark blue, blue, cyan, green, yellow, red, white: monotone in lightness, readable in print.
vec3 colourScale(float t) {
  const vec3 stops[7] = vec3[](vec3(0.02, 0.02, 0.25), vec3(0.1, 0.2, 0.8), vec3(0.0, 0.7, 0.9), vec3(0.1, 0.8, 0.2),
                               vec3(0.95, 0.9, 0.1), vec3(0.9, 0.2, 0.1), vec3(1.0));
  float x = clamp(t, 0.0, 1.0) * 6.0;
  int i = min(int(x), 5);
  return mix(stops[i], stops[i + 1], x - float(i));
}

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

// Blue (negative: the render is darker than the comparison), white at zero, red (positive).
vec3 divergingScale(float t) {
  float x = clamp(t, -1.0, 1.0);
  return x < 0.0 ? mix(vec3(1.0), vec3(0.1, 0.25, 0.85), -x) : mix(vec3(1.0), vec3(0.85, 0.1, 0.1), x);
}

bool finiteAndCovered(vec4 B) { return B.a > 0.0 && !any(isnan(B.rgb)) && !any(isinf(B.rgb)); }

// The displayed (exposed, tone-mapped) luminance of a pixel, and whether a surface is there.
float shown(ivec2 p, out bool covered) {
  vec4 B = texelFetch(linearRadiosity, clamp(p, ivec2(0), textureSize(linearRadiosity, 0) - 1), 0);
  covered = finiteAndCovered(B);
  return covered ? luminance(toneMap(B.rgb, exposureScale)) : 0.0;
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  ivec2 size = textureSize(linearRadiosity, 0);
  if ((view == VIEW_VALUE || view == VIEW_DIFFERENCE || view == VIEW_STANDARD_ERROR) && p.x >= size.x - 16) {
    // The colour bar. Value: bottom 0, top 1; difference: -scale .. +scale; standard error: 0 .. scale.
    float t = gl_FragCoord.y / float(size.y);
    vec3 bar = view == VIEW_DIFFERENCE ? divergingScale(2.0 * t - 1.0) : colourScale(t);
    display = vec4(p.x < size.x - 12 ? background : bar, 1.0);
    return;
  }
  vec4 B = texelFetch(linearRadiosity, p, 0);
  bool covered = finiteAndCovered(B);
  if (!covered) {
    display = vec4(background, 1.0);
    return;
  }
  vec3 shownColour = toneMap(B.rgb, exposureScale);
  float v = luminance(shownColour);
  if (view == VIEW_DIFFERENCE) {
    ivec2 q = ivec2(gl_FragCoord.xy * vec2(textureSize(comparisonRadiosity, 0)) / vec2(size));
    vec4 C = texelFetch(comparisonRadiosity, q, 0);
    if (!finiteAndCovered(C)) {
      display = vec4(background, 1.0);
      return;
    }
    float shownC = luminance(comparisonLinear ? toneMap(C.rgb, exposureScale) : C.rgb);
    display = vec4(divergingScale((v - shownC) / differenceScale), 1.0);
    return;
  }
  if (view == VIEW_STANDARD_ERROR) {
    vec4 error = texelFetch(comparisonRadiosity, p, 0);
    if (!finiteAndCovered(error)) {
      display = vec4(background, 1.0);
      return;
    }
    float higher = luminance(toneMap(B.rgb + max(error.rgb, vec3(0.0)), exposureScale));
    display = vec4(colourScale((higher - v) / differenceScale), 1.0);
    return;
  }
  if (view == VIEW_VALUE) {
    display = vec4(colourScale(v), 1.0);
  } else if (view == VIEW_GRADIENT) {
    // Central differences where both neighbours are surface, one-sided otherwise.
    bool l, r, d, u;
    float vl = shown(p - ivec2(1, 0), l), vr = shown(p + ivec2(1, 0), r);
    float vd = shown(p - ivec2(0, 1), d), vu = shown(p + ivec2(0, 1), u);
    float gx = l && r ? 0.5 * (vr - vl) : (r ? vr - v : (l ? v - vl : 0.0));
    float gy = d && u ? 0.5 * (vu - vd) : (u ? vu - v : (d ? v - vd : 0.0));
    display = vec4(colourScale(length(vec2(gx, gy)) / gradientScale), 1.0);
  } else if (view == VIEW_ISOLINES) {
    // A line where the level index changes towards the right or upper neighbour.
    bool r, u;
    float vr = shown(p + ivec2(1, 0), r), vu = shown(p + ivec2(0, 1), u);
    float n = float(isolineCount);
    bool line = (r && floor(vr * n) != floor(v * n)) || (u && floor(vu * n) != floor(v * n));
    display = vec4(line ? vec3(0.0) : shownColour, 1.0);
  }
}
