#pragma once
// Draws a radiosity mesh with any interpolant of C&W §9.2: flat, Gouraud on triangles
// (perspective-correct or screen-space), scanline Gouraud on the element polygons (fig. 9.7),
// and bilinear, quadratic, C1 quadratic and Clough-Tocher evaluated exactly per pixel, or a
// linear image in their place (a final gather); exposure and sRGB tone mapping; the element-edge
// overlay. Needs a current OpenGL 4.5 core context (EglContext, or the viewer's window).
#include "core/camera.h"
#include "core/image.h"
#include "gl/bezier_pass.h"
#include "gl/buffer_storage.h"
#include "gl/deferred_pass.h"
#include "gl/display_views.h"
#include "gl/gl_object.h"
#include "gl/polygon_pass.h"
#include "gl/prepared_mesh.h"
#include "gl/render_targets.h"
#include "gl/shader_program.h"
#include "interp/interpolant.h"
#include "mesh/radiosity_mesh.h"
#include "mesh/topology.h"

#include <epoxy/gl.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace radview::gl {

struct RenderSettings {
  Method method = Method::Gouraud;
  bool perspectiveCorrect = true;  // Gouraud: false interpolates linearly in screen space
  CloughTocherVariant cloughTocher = CloughTocherVariant::AffineInvariant;
  // Quadratic and C1 methods: 0 exact per pixel, 1..64 tessellated at that level,
  // kAdaptiveTessellation at the level that keeps the display error under the tolerance.
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
  double differenceScale = 4.0 / 255.0;
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

struct DeferredSetup;  // gl/method_pieces.h

class MeshRenderer {
 public:
  MeshRenderer();
  ~MeshRenderer();
  MeshRenderer(const MeshRenderer&) = delete;
  MeshRenderer& operator=(const MeshRenderer&) = delete;

  void setMesh(const RadiosityMesh& mesh);  // prepareMesh, then adoptMesh
  // Uploads a mesh prepared on any thread (gl/prepared_mesh.h): what the renderer draws from now.
  void adoptMesh(PreparedMesh&& prepared);
  void render(const Camera& camera, const RenderSettings& settings, int width, int height);

  // The C1 methods per pixel, set up beside a frame loop (the viewer's): where render() would
  // now have to build `settings`' pieces, the part of that which needs no OpenGL (seconds at
  // 10^6 elements), as a job that may run on any thread; else an empty function. adoptPieces
  // then uploads the result on this renderer's thread, and render() draws it without building;
  // a set-up for a mesh no longer drawn is dropped.
  std::function<DeferredSetup()> piecesSetup(const RenderSettings& settings) const;
  void adoptPieces(const DeferredSetup& setup, bool splitLines);

  // The image a difference view compares with: a linear file or display colour, any size (the
  // view samples it at its own resolution; displayDifference needs equal sizes).
  void setReferenceImage(const ReferenceImage& reference);
  bool hasReferenceImage() const { return referenceTexture_ != 0; }

  // An image shown in place of the mesh's interpolated radiosity (the viewer's final gather,
  // C&W §9.3.1) until clearShownImage: linear, row 0 the top, alpha coverage, any size (stretched
  // to the render's, nearest texel). Pass 1 still draws the mesh, flat, for the depth the
  // overlays are tested against; then the image replaces its colour, and the tone map, the views
  // and the overlays treat it as they treat a method's render. Throws Error for a size this
  // OpenGL cannot hold.
  void setShownImage(const LinearImage& image);
  void clearShownImage();
  bool hasShownImage() const { return shownTexture_ != 0; }

  Image readDisplay() const;
  LinearImage readLinear() const;
  // What the last difference view compared with, as a reference for displayDifference: the
  // comparison method's linear image, or the reference image.
  ReferenceImage readComparison() const;
  // Copies the last rendered image into the window's back buffer, its columns from `left` on
  // (the viewer frames the scene beside its panel), at width x height framebuffer pixels.
  void presentToDefaultFramebuffer(int left, int width, int height) const;
  // GPU time of the most recent render() whose timer query is ready, in ms (0 until one is).
  // It never waits: the viewer's figure, two frames late.
  double gpuFrameMs() const { return gpuFrameMs_; }
  // GPU time of the last render(), in ms, waiting for it to finish if need be: what a benchmark
  // times, frame by frame. Throws Error before the first render.
  double lastFrameGpuMs() const;
  size_t triangleCount() const { return triangleVertices_ / 3; }
  // The Bezier pieces of the last quadratic or C1 frame: patches, draws, levels, triangles (for
  // the C1 methods per pixel: the element triangles of the deferred pass, at level 1).
  const TessellationStatistics& tessellationStatistics() const { return statistics_; }
  size_t tVertexCount() const { return size_t(tVertexMarkers_); }

 private:
  // Storage of the mesh's buffers, declared first: freed after the buffers that use it.
  BufferStorage storage_;
  RenderTargets targets_;
  ShaderProgram meshProgram_{{"mesh.vert", "mesh.frag"}};
  ShaderProgram toneMapProgram_{{"fullscreen.vert", "tonemap.frag"}};
  ShaderProgram falseColourProgram_{{"fullscreen.vert", "false_colour.frag"}};
  ShaderProgram linesProgram_{{"lines.vert", "lines.frag"}};
  PolygonPass polygons_{storage_};  // scanline Gouraud, bilinear, serendipity quads
  ShaderProgram overlayProgram_{{"overlay.vert", "overlay.frag"}};
  GlObject overlayVao_, overlayVbo_;
  GLsizei discontinuityVertices_ = 0, tVertexMarkers_ = 0;  // in overlayVbo_: the edges, then the markers
  GlObject meshVao_, meshVbo_, edgeVao_, edgeVbo_, emptyVao_;
  GLsizei triangleVertices_ = 0, edgeVertices_ = 0;
  // The Bezier pieces of the quadratic and C1 methods, built when first drawn (and again when
  // the method or the Clough-Tocher variant changes): for the deferred pass (the C1 methods per
  // pixel), else for the Bezier pass, releasing the other's.
  void uploadPatches(const RenderSettings& settings, const BezierEvaluation& evaluation);
  void uploadSplit(const std::vector<glm::vec3>& split, int key);  // the split lines of the pieces `key`, or none
  // Whether `method` is drawn by the deferred pass with this evaluation: the C1 methods per
  // pixel, on the flat surface.
  static bool isDeferred(Method method, const BezierEvaluation& evaluation);
  // Whether `method` is the quadratic one per pixel on the flat surface: Gouraud's triangles
  // for its linear elements (the first linearForQuadraticVertices_ of the mesh's), the Bezier
  // pass for its 6-node triangles alone (kQuadraticTrianglesKey), the polygon pass for its
  // serendipity quads.
  static bool isQuadraticPerPixel(Method method, const BezierEvaluation& evaluation);
  // drawRadiosity's passes, one per way a method is drawn (MethodInfo::gpu).
  void drawTriangles(Method method, bool perspectiveCorrect, const glm::mat4& clipFromWorld, GLsizei vertices);
  void drawQuadraticPerPixel(const BezierEvaluation& evaluation, const glm::mat4& clipFromWorld, int width, int height,
                             bool comparison);
  void drawDeferred(Method method, const RenderSettings& settings, const glm::mat4& clipFromWorld, GLuint framebuffer,
                    bool comparison, bool depthOnly);
  void drawTessellated(Method method, const RenderSettings& settings, BezierEvaluation evaluation,
                       const glm::mat4& clipFromWorld, int width, int height);
  static constexpr int kQuadraticTrianglesKey = 1 << 20;  // a Bezier pass's key: beyond every piecesKey
  GLsizei linearForQuadraticVertices_ = 0;
  // A frame's passes, in order. What can throw is uploaded first (the mesh when T-vertex repair
  // changes, the method's and the comparison's pieces, the control net); it returns whether
  // the control net is drawn.
  struct FrameComparison {
    bool method = false, image = false;  // the difference view subtracts another method / an image
  };
  bool uploadForFrame(const RenderSettings& settings, const Camera& viewCamera, bool compareMethod);
  void beginTimer();
  // Pass 1: linear radiosity and depth, the comparison method's first into its own target.
  void drawRadiosityPass(const RenderSettings& settings, const Camera& camera, const glm::mat4& clipFromWorld,
                         int width, int height, bool compareMethod);
  // Pass 2: the tone map or a false-colour view into the display target.
  void drawDisplayPass(const RenderSettings& settings, const FrameComparison& comparison);
  // Pass 3: the overlays, depth-tested against the surfaces pushed back (drawOverlayDepth).
  void drawOverlays(const RenderSettings& settings, const Camera& camera, const glm::mat4& clipFromWorld, int width,
                    int height, bool drawNet);
  void drawOverlayDepth(const RenderSettings& settings, const Camera& camera, const glm::mat4& clipFromWorld, int width,
                        int height);
  void drawLines(GLuint vao, GLsizei vertices, const glm::vec4& colour, const glm::mat4& clipFromWorld);
  // Pass 1 for `method` into the bound framebuffer (cleared there): linear radiosity and depth;
  // `comparison` when it is the difference view's comparison. `depthOnly`: the depth that
  // leaves (the caller masks colour writes), without the deferred evaluation.
  void drawRadiosity(Method method, const RenderSettings& settings, const Camera& camera,
                     const glm::mat4& clipFromWorld, int width, int height, bool comparison, bool depthOnly);
  // The comparison method's pieces, when it is a Bezier method (its own pass: switching
  // between the two every frame would rebuild them every frame).
  BezierPass comparisonPass_;
  int comparisonPatchesFor_ = -1;
  DeferredPass deferred_, comparisonDeferred_;  // the C1 methods per pixel, the method's and the comparison's
  int deferredFor_ = -1, comparisonDeferredFor_ = -1;
  TessellationStatistics statistics_;  // of the last frame's method
  GlObject referenceTexture_;
  GlObject shownTexture_, shownFbo_;  // setShownImage's, and a framebuffer to blit it from
  int shownWidth_ = 0, shownHeight_ = 0;
  ReferenceImage reference_;                       // as set, for readComparison
  bool comparedWithImage_ = false;                 // what the last difference view used
  std::shared_ptr<const RadiosityMesh> original_;  // as set
  std::shared_ptr<const RadiosityMesh>
      mesh_;  // as drawn: the original, or with its T-vertices repaired, moved by -origin_
  std::shared_ptr<const MeshTopology> topology_;  // mesh_'s, built once for the display mesh and every method's pieces
  Vec3 origin_{0.0};                              // the world point at the origin of the coordinates the GPU sees
  double brightestLuminance_ = 1.0;               // of the non-emitting elements' nodes, for the surface view
  // The Bezier pass's settings for this frame.
  BezierEvaluation bezierEvaluation(const RenderSettings& settings, const Camera& camera) const;
  bool repairedDrawn_ = false;
  BezierPass bezierPass_;
  GlObject splitVao_, splitVbo_;
  GLsizei splitVertices_ = 0;
  // The radiosity surface's control net, for the pieces and height it was built for.
  void uploadControlNet(double heightScale);
  GlObject netVao_, netVbo_;
  GLsizei netVertices_ = 0;
  std::array<double, 2> netFor_{-1, 0};  // patchesFor_, height scale
  int patchesFor_ = -1;                  // the method and variant the Bezier pass holds, -1 none
  int splitFor_ = -1;                    // the method and variant splitVbo_ holds
  // Timer queries, two in flight so reading a result never stalls the frame (beginTimer).
  std::array<GlObject, 2> timerQueries_;
  GlObject eyePlane_{GlKind::Buffer};  // shaders/lib/eye_plane.glsl's uniform block
  int frame_ = 0;
  double gpuFrameMs_ = 0.0;
};

// Reads the window's back buffer (viewer screenshots include the panel).
Image readDefaultFramebuffer(int width, int height);

}  // namespace radview::gl
