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
#include "gl/display_pass.h"
#include "gl/display_views.h"
#include "gl/gl_object.h"
#include "gl/gpu_timer.h"
#include "gl/method_pieces.h"
#include "gl/overlay_pass.h"
#include "gl/polygon_pass.h"
#include "gl/prepared_mesh.h"
#include "gl/raster_pass.h"
#include "gl/render_settings.h"
#include "gl/render_targets.h"
#include "gl/shader_program.h"
#include "gl/shown_image.h"
#include "interp/interpolant.h"
#include "mesh/radiosity_mesh.h"
#include "mesh/topology.h"

#include <epoxy/gl.h>

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace radview::gl {

class MeshRenderer {
 public:
  MeshRenderer();
  ~MeshRenderer();
  MeshRenderer(const MeshRenderer&) = delete;
  MeshRenderer& operator=(const MeshRenderer&) = delete;

  void setMesh(const RadiosityMesh& mesh);  // prepareMesh of a copy, then adoptMesh
  void setMesh(std::shared_ptr<const RadiosityMesh> mesh);  // the same, sharing the mesh
  // The drawn mesh after a continuity edit (edit/continuity_edit.h), with its topology
  // (MeshTopology(mesh), which the editor keeps). An edit keeps every position, value and
  // element, so the display triangles, which carry no node ids, stay as they are; the overlays
  // and every method's pieces are built again.
  void setEditedMesh(const RadiosityMesh& mesh, std::shared_ptr<const MeshTopology> topology);
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
  bool hasReferenceImage() const { return display_.hasReferenceImage(); }

  // An image shown in place of the mesh's interpolated radiosity (the viewer's final gather,
  // C&W §9.3.1) until clearShownImage: linear, row 0 the top, alpha coverage, any size (stretched
  // to the render's, nearest texel). Pass 1 still draws the mesh, flat, for the depth the
  // overlays are tested against; then the image replaces its colour, and the tone map, the views
  // and the overlays treat it as they treat a method's render. Throws Error for a size this
  // OpenGL cannot hold.
  void setShownImage(const LinearImage& image);
  void clearShownImage();
  bool hasShownImage() const { return !shown_.empty(); }

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
  double gpuFrameMs() const { return timer_.recentMs(); }
  // GPU time of the last render(), in ms, waiting for it to finish if need be: what a benchmark
  // times, frame by frame. Throws Error before the first render.
  double lastFrameGpuMs() const { return timer_.lastMs(); }
  size_t triangleCount() const { return size_t(raster_.vertices() / 3); }
  // The Bezier pieces of the last quadratic or C1 frame: patches, draws, levels, triangles (for
  // the C1 methods per pixel: the element triangles of the deferred pass, at level 1).
  const TessellationStatistics& tessellationStatistics() const { return statistics_; }
  size_t tVertexCount() const { return overlays_.tVertexCount(); }
  // The topology of the mesh last given (MeshTopology of it, as its editor keeps one); null while
  // it is drawn with its T-vertices repaired, when the renderer holds the repaired mesh's.
  std::shared_ptr<const MeshTopology> givenMeshTopology() const { return repairedDrawn_ ? nullptr : topology_; }

 private:
  // A frame's steps, in order (render reads as this list).
  struct FrameComparison {
    bool method = false, image = false;  // the difference view subtracts another method / an image
    bool standardErrors = false;         // the standard-error view, drawn into the comparison target
  };
  // What can throw is uploaded first: the mesh when T-vertex repair changes, the method's and the
  // comparison's pieces, the control net. Returns whether the control net is drawn.
  bool uploadForFrame(const RenderSettings& settings, const Camera& viewCamera, bool compareMethod);
  // Pass 1: linear radiosity and depth, the comparison method's first into its own target; a
  // shown image then copied over the colour.
  void drawRadiosityPass(const RenderSettings& settings, const Camera& camera, const glm::mat4& clipFromWorld,
                         int width, int height, const FrameComparison& comparison);
  // Pass 3: the overlays, depth-tested against the surfaces pushed back (drawOverlayDepth).
  void drawOverlays(const RenderSettings& settings, const Camera& camera, const glm::mat4& clipFromWorld, int width,
                    int height, bool drawNet);
  void drawOverlayDepth(const RenderSettings& settings, const Camera& camera, const glm::mat4& clipFromWorld, int width,
                        int height);

  // Pass 1 for `method` into the bound framebuffer (cleared there): linear radiosity and depth;
  // `comparison` when it is the difference view's comparison. `depthOnly`: the depth that
  // leaves (the caller masks colour writes), without the deferred evaluation. One branch per way
  // a method is drawn (MethodInfo::gpu):
  void drawRadiosity(Method method, const RenderSettings& settings, const Camera& camera,
                     const glm::mat4& clipFromWorld, int width, int height, bool comparison, bool depthOnly);
  void drawQuadraticPerPixel(const BezierEvaluation& evaluation, const glm::mat4& clipFromWorld, int width, int height,
                             bool comparison);
  void drawDeferred(Method method, const RenderSettings& settings, const glm::mat4& clipFromWorld, GLuint framebuffer,
                    bool comparison, bool depthOnly);
  void drawTessellated(Method method, const RenderSettings& settings, BezierEvaluation evaluation,
                       const glm::mat4& clipFromWorld, int width, int height);

  // The Bezier pieces of the quadratic and C1 methods, built when first drawn (and again when
  // the method or the Clough-Tocher variant changes): for the deferred pass (the C1 methods per
  // pixel), else for the Bezier pass, releasing the other's.
  // With `sameSurfaces` (a continuity edit of the mesh drawn): the display triangles, and the
  // element edges where `prepared` has none, stay.
  void adoptMesh(PreparedMesh&& prepared, bool sameSurfaces);
  void uploadTriangles(const DrawnTriangles& triangles);
  // Whether `method` draws the display triangles (the raster and polygon passes' input).
  static bool drawsTriangles(Method method);
  void uploadPatches(const RenderSettings& settings, const BezierEvaluation& evaluation);
  void uploadSplit(const std::vector<glm::vec3>& split, std::optional<PiecesKey> key);  // of the pieces `key`
  void uploadControlNet(double heightScale);  // for the Bezier pass's pieces at this height
  // Whether `method` is drawn by the deferred pass with this evaluation: the C1 methods per
  // pixel, on the flat surface.
  static bool isDeferred(Method method, const BezierEvaluation& evaluation);
  // Whether `method` is the quadratic one per pixel on the flat surface: Gouraud's triangles
  // for its linear elements (RasterPass::linearForQuadraticVertices), the Bezier
  // pass for its 6-node triangles alone, the polygon pass for its serendipity quads.
  static bool isQuadraticPerPixel(Method method, const BezierEvaluation& evaluation);
  // The Bezier pass's settings for this frame.
  BezierEvaluation bezierEvaluation(const RenderSettings& settings, const Camera& camera) const;

  // Storage of the mesh's buffers, declared first: freed after the buffers that use it.
  BufferStorage storage_;
  RenderTargets targets_;
  RasterPass raster_{storage_};     // flat and Gouraud, and the triangles the polygon pass draws over
  bool trianglesUploaded_ = false;  // raster_'s and polygons_' triangles, built when a method first draws them
  // The standard-error view's triangles, carrying the nodes' standard errors: built when that
  // view is first drawn for the mesh, and freed with the mesh.
  RasterPass errorRaster_{storage_};
  bool errorsUploaded_ = false;
  PolygonPass polygons_{storage_};  // scanline Gouraud, bilinear, serendipity quads
  OverlayPass overlays_{storage_};
  // The method's pieces, and the comparison method's when it is a Bezier method (its own
  // passes: switching between the two every frame would rebuild them every frame).
  BezierPass bezierPass_, comparisonPass_;
  DeferredPass deferred_, comparisonDeferred_;  // the C1 methods per pixel
  std::optional<PiecesKey> patchesFor_, comparisonPatchesFor_, deferredFor_, comparisonDeferredFor_;
  std::optional<PiecesKey> splitFor_;  // the pieces whose split lines the overlays hold
  struct ControlNetKey {
    std::optional<PiecesKey> pieces;
    double heightScale = 0.0;
    bool operator==(const ControlNetKey& other) const {
      return pieces == other.pieces && heightScale == other.heightScale;
    }
  };
  std::optional<ControlNetKey> netFor_;
  TessellationStatistics statistics_;  // of the last frame's method
  DisplayPass display_;
  bool comparedWithImage_ = false;  // what the last difference view used
  ShownImage shown_;
  std::shared_ptr<const RadiosityMesh> original_;  // as set
  // As drawn: the original, or with its T-vertices repaired, moved by -origin_.
  std::shared_ptr<const RadiosityMesh> mesh_;
  // mesh_'s (of its positions before the move), built once for the display mesh and every method's pieces
  std::shared_ptr<const MeshTopology> topology_;
  Vec3 origin_{0.0};                              // the world point at the origin of the coordinates the GPU sees
  double brightestLuminance_ = 1.0;               // of the non-emitting elements' nodes, for the surface view
  bool repairedDrawn_ = false;
  GpuTimer timer_;
  GlObject eyePlane_{GlKind::Buffer};  // shaders/lib/eye_plane.glsl's uniform block
};

// Reads the window's back buffer (viewer screenshots include the panel).
Image readDefaultFramebuffer(int width, int height);

}  // namespace radview::gl
