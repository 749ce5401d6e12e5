#pragma once
// What a frame of MeshRenderer shows: the method and its options, the display transform and
// view, and the overlays.
#include "gl/display_views.h"
#include "interp/interpolant.h"

#include <glm/glm.hpp>

namespace radview::gl {

struct RenderSettings {
  Method method = Method::Gouraud;
  bool perspectiveCorrect = true;  // Gouraud: false interpolates linearly in screen space
  CloughTocherVariant cloughTocher = CloughTocherVariant::AffineInvariant;
  ThinPlateSettings thinPlate;  // Method::ThinPlate's smoothing
  // Quadratic and C1 methods: 0 exact per pixel, 1..64 tessellated at that level,
  // kAdaptiveTessellation (gl/bezier_pass.h) at the level that keeps the display error under the tolerance.
  int tessellation = 0;
  double tessellationTolerance = 0.5 / 255.0;
  double exposure = 0.0;  // stops: B is scaled by 2^exposure before display
  DisplayView view = DisplayView::Normal;
  double gradientScale = 0.02;  // gradient view: display units per pixel at the top of the scale
  int isolineCount = 16;        // isolines view: levels across the display range
  // Difference view: what the render is compared with, the other method (evaluated exactly per
  // pixel, so a tessellated method against itself shows its tessellation error) or the
  // reference image (setReferenceImage); and the difference at the ends of the colour scale,
  // in display units.
  enum class Comparison : int { Method, Image };
  Comparison comparison = Comparison::Method;
  Method comparisonMethod = Method::CloughTocher;
  double differenceScale = 4.0 / 255.0;  // also the top of the standard-error view's scale
  bool elementEdges = false;
  bool discontinuityEdges = false;     // coloured by continuity order (C-1, C0)
  bool tVertices = false;              // markers
  bool repairTVertices = false;        // draw elements with T-vertices as triangles through them (Baum et al.)
  bool splitLines = false;             // C1 methods: the lines that cut elements into Bezier pieces
  bool tessellationTriangles = false;  // tessellated methods: the generated triangles
  // Quadratic and C1 methods: the radiosity surface of fig. 9.13, B as a height over each
  // element, its tallest point (of non-emitting elements) at this fraction of the scene's
  // size; 0 is off. Drawn tessellated (adaptively when the method is set to per pixel).
  double surfaceHeight = 0.0;
  bool controlNet = false;  // with the radiosity surface: its Bezier control net
  glm::vec3 background{0.08f, 0.08f, 0.09f};
  glm::vec4 edgeColour{0.0f, 0.0f, 0.0f, 1.0f};
};

}  // namespace radview::gl
