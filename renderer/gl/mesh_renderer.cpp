#include "gl/mesh_renderer.h"

#include "core/error.h"
#include "core/strings.h"
#include "gl/image_transfer.h"
#include "gl/patch_vertices.h"
#include "mesh/display_mesh.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace radview::gl {

namespace {

// The pieces `method` is drawn from under `settings`.
PiecesKey piecesKey(Method method, const RenderSettings& settings) {
  return {method, settings.cloughTocher, false, settings.thinPlate};
}

}  // namespace

MeshRenderer::MeshRenderer() = default;

MeshRenderer::~MeshRenderer() = default;

void MeshRenderer::setMesh(const RadiosityMesh& mesh) { setMesh(std::make_shared<const RadiosityMesh>(mesh)); }

void MeshRenderer::setMesh(std::shared_ptr<const RadiosityMesh> mesh) { adoptMesh(prepareMesh(std::move(mesh), {})); }

void MeshRenderer::setEditedMesh(const RadiosityMesh& mesh, std::shared_ptr<const MeshTopology> topology) {
  // Drawn repaired, the elements are not the edited mesh's: all is built again.
  if (repairedDrawn_) return setMesh(mesh);
  PrepareOptions options;
  options.elementEdges = false;
  options.topology = std::move(topology);
  adoptMesh(prepareMesh(std::make_shared<const RadiosityMesh>(mesh), options), true);
}

void MeshRenderer::adoptMesh(PreparedMesh&& prepared) { adoptMesh(std::move(prepared), false); }

void MeshRenderer::adoptMesh(PreparedMesh&& prepared, bool sameSurfaces) {
  errorRaster_.setMesh({}, 0);
  errorsUploaded_ = false;
  overlays_.setMesh(prepared.display, !prepared.elementEdges && sameSurfaces);
  polygons_.setMesh(prepared.drawn);
  if (prepared.triangles) {
    uploadTriangles(*prepared.triangles);
    trianglesUploaded_ = true;
  } else if (!sameSurfaces) {
    raster_.setMesh({}, 0);
    polygons_.setTriangles({});
    trianglesUploaded_ = false;
  }
  original_ = std::move(prepared.original);
  mesh_ = std::move(prepared.drawn);
  topology_ = std::move(prepared.topology);
  origin_ = prepared.origin;
  brightestLuminance_ = prepared.brightestLuminance;
  repairedDrawn_ = prepared.repairedTVertices;
  patchesFor_ = comparisonPatchesFor_ = deferredFor_ = comparisonDeferredFor_ = splitFor_ = std::nullopt;
  netFor_ = std::nullopt;
}

void MeshRenderer::uploadTriangles(const DrawnTriangles& triangles) {
  raster_.setMesh(triangles.vertices, triangles.linearForQuadraticVertices);
  polygons_.setTriangles(triangles.vertices);
}

bool MeshRenderer::drawsTriangles(Method method) {
  switch (methodInfo(method).gpu) {
    case GpuPass::Triangles:
    case GpuPass::ScanlinePolygons:
    case GpuPass::BilinearPolygons:
    case GpuPass::LagrangePieces:  // its linear elements, and the serendipity quads
      return true;
    case GpuPass::PowellSabinPieces:
    case GpuPass::CloughTocherPieces:
      return false;
  }
  return true;
}

bool MeshRenderer::isDeferred(Method method, const BezierEvaluation& evaluation) {
  return resolvesDeferred(methodInfo(method).gpu) && evaluation.tessellation == 0;
}

bool MeshRenderer::isQuadraticPerPixel(Method method, const BezierEvaluation& evaluation) {
  return methodInfo(method).gpu == GpuPass::LagrangePieces && evaluation.tessellation == 0;
}

void MeshRenderer::uploadPatches(const RenderSettings& settings, const BezierEvaluation& evaluation) {
  const bool deferred = isDeferred(settings.method, evaluation);
  const bool quadraticTriangles = isQuadraticPerPixel(settings.method, evaluation);
  const PiecesKey wanted =
      quadraticTriangles ? PiecesKey::quadraticTriangles() : piecesKey(settings.method, settings);
  if ((deferred ? deferredFor_ : patchesFor_) == wanted && (!settings.splitLines || splitFor_ == wanted)) return;
  if (deferred) {
    adoptPieces(prepareDeferred(mesh_, topology_, wanted), settings.splitLines);
    return;
  }
  // One of the two passes holds the method's pieces at a time, the other's freed first: memory
  // stays what the view needs.
  deferred_.clear();
  deferredFor_ = std::nullopt;
  std::vector<glm::vec3> split;
  bezierPass_.upload(quadraticTriangles ? quadraticTriangleVertices(*mesh_)
                                        : pieceVertices(*mesh_, topology_, wanted, settings.splitLines ? &split : nullptr),
                     pieceDegree(methodInfo(settings.method).gpu));
  patchesFor_ = wanted;
  uploadSplit(split, settings.splitLines ? std::optional(wanted) : std::nullopt);
}

std::function<DeferredSetup()> MeshRenderer::piecesSetup(const RenderSettings& settings) const {
  const bool flatSurface = settings.surfaceHeight == 0.0 || settings.view == DisplayView::Difference ||
                           settings.view == DisplayView::StandardError;
  const PiecesKey key = piecesKey(settings.method, settings);
  const bool built = deferredFor_ == key && (!settings.splitLines || splitFor_ == key);
  if (built || hasShownImage() || settings.repairTVertices != repairedDrawn_ || settings.tessellation != 0 ||
      !flatSurface || !resolvesDeferred(methodInfo(settings.method).gpu))
    return {};
  return [mesh = mesh_, topology = topology_, key] { return prepareDeferred(mesh, topology, key); };
}

void MeshRenderer::adoptPieces(const DeferredSetup& setup, bool splitLines) {
  if (setup.mesh != mesh_) return;
  bezierPass_.upload({}, 3);
  patchesFor_ = std::nullopt;
  std::vector<glm::vec3> split;
  uploadDeferred(setup, deferred_, splitLines ? &split : nullptr);
  deferredFor_ = setup.key();
  uploadSplit(split, splitLines ? deferredFor_ : std::nullopt);
}

void MeshRenderer::uploadSplit(const std::vector<glm::vec3>& split, std::optional<PiecesKey> key) {
  overlays_.setSplitLines(split);
  splitFor_ = key;
}

void MeshRenderer::uploadControlNet(double heightScale) {
  const ControlNetKey wanted{patchesFor_, heightScale};
  if (netFor_ == wanted) return;
  overlays_.setControlNet(controlNetLines(bezierPass_.vertices(), bezierPass_.degree(), heightScale));
  netFor_ = wanted;
}

BezierEvaluation MeshRenderer::bezierEvaluation(const RenderSettings& settings, const Camera& camera) const {
  BezierEvaluation evaluation;
  evaluation.tessellation = settings.tessellation;
  evaluation.tolerance = settings.tessellationTolerance;
  evaluation.exposureScale = std::exp2(settings.exposure);
  if (settings.surfaceHeight > 0.0) {
    evaluation.surfaceHeight = settings.surfaceHeight * mesh_->bounds().diagonal() / brightestLuminance_;
    evaluation.eye = glm::vec3(camera.eye - origin_);
    if (evaluation.tessellation == 0) evaluation.tessellation = kAdaptiveTessellation;
  }
  return evaluation;
}

void MeshRenderer::drawRadiosity(Method method, const RenderSettings& settings, const Camera& camera,
                                 const glm::mat4& clipFromWorld, int width, int height, bool comparison,
                                 bool depthOnly) {
  GLint framebuffer = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
  const float clearLinear[] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearNamedFramebufferfv(GLuint(framebuffer), GL_COLOR, 0, clearLinear);
  glClearNamedFramebufferfi(GLuint(framebuffer), GL_DEPTH_STENCIL, 0, 1.0f, 0);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);  // radiosity surfaces are seen from both sides in a viewer
  const BezierEvaluation evaluation = bezierEvaluation(settings, camera);
  switch (methodInfo(method).gpu) {
    case GpuPass::Triangles:
      raster_.draw(method, settings.perspectiveCorrect, clipFromWorld, raster_.vertices());
      break;
    case GpuPass::ScanlinePolygons:
      polygons_.draw(PolygonPass::Mode::Scanline, raster_.vertexArray(), raster_.vertices(), clipFromWorld, width,
                     height);
      break;
    case GpuPass::BilinearPolygons:
      polygons_.draw(PolygonPass::Mode::Bilinear, raster_.vertexArray(), raster_.vertices(), clipFromWorld, width,
                     height);
      break;
    case GpuPass::LagrangePieces:
      if (isQuadraticPerPixel(method, evaluation))
        drawQuadraticPerPixel(evaluation, clipFromWorld, width, height, comparison);
      else
        drawTessellated(method, settings, evaluation, clipFromWorld, width, height);
      break;
    case GpuPass::PowellSabinPieces:
    case GpuPass::CloughTocherPieces:
      if (isDeferred(method, evaluation))
        drawDeferred(method, settings, clipFromWorld, GLuint(framebuffer), comparison, depthOnly);
      else
        drawTessellated(method, settings, evaluation, clipFromWorld, width, height);
      break;
  }
}

// Linear elements are linear under the quadratic method too: Gouraud's triangles,
// perspective-correct; then the 6-node triangles' pieces and the serendipity quads.
void MeshRenderer::drawQuadraticPerPixel(const BezierEvaluation& evaluation, const glm::mat4& clipFromWorld, int width,
                                         int height, bool comparison) {
  raster_.draw(Method::Gouraud, true, clipFromWorld, raster_.linearForQuadraticVertices());
  BezierPass& pass = comparison && patchesFor_ != PiecesKey::quadraticTriangles() ? comparisonPass_ : bezierPass_;
  if (!pass.vertices().empty()) pass.draw(clipFromWorld, evaluation);
  polygons_.drawSerendipity(clipFromWorld, width, height);
  const size_t pieces =
      size_t(raster_.linearForQuadraticVertices() + polygons_.serendipityVertices()) / 3 + pass.vertices().size() / 3;
  statistics_ = {pieces, 3, 1.0, pieces};
}

void MeshRenderer::drawDeferred(Method method, const RenderSettings& settings, const glm::mat4& clipFromWorld,
                                GLuint framebuffer, bool comparison, bool depthOnly) {
  // The comparison shares the method's pieces when it is the same method per pixel.
  const bool own = comparison && deferredFor_ != piecesKey(method, settings);
  DeferredPass& pass = own ? comparisonDeferred_ : deferred_;
  if (depthOnly)
    pass.drawDepth(clipFromWorld);
  else
    pass.draw(clipFromWorld, framebuffer);
  statistics_ = {pass.triangles(), 2, 1.0, pass.triangles()};
}

void MeshRenderer::drawTessellated(Method method, const RenderSettings& settings, BezierEvaluation evaluation,
                                   const glm::mat4& clipFromWorld, int width, int height) {
  BezierPass& pass = method == settings.method ? bezierPass_ : comparisonPass_;
  // Serendipity quads are exact per pixel in the polygon pass; the radiosity surface draws
  // them from their (linear) pieces, which it can lift.
  const bool serendipityPass = methodInfo(method).gpu == GpuPass::LagrangePieces && evaluation.surfaceHeight == 0.0;
  if (serendipityPass) evaluation.pieces = pass.vertices().size() / 3 - size_t(polygons_.serendipityVertices() / 3);
  pass.draw(clipFromWorld, evaluation);
  statistics_ = pass.statistics();
  if (serendipityPass) polygons_.drawSerendipity(clipFromWorld, width, height);
}

void MeshRenderer::render(const Camera& viewCamera, const RenderSettings& requested, int width, int height) {
  RenderSettings settings = requested;
  // A difference compares the same surfaces, and standard errors lie on them: the raised
  // radiosity surface has no counterpart.
  if (settings.view == DisplayView::Difference || settings.view == DisplayView::StandardError)
    settings.surfaceHeight = 0.0;
  // A shown image needs only the surfaces' depth from pass 1: the cheapest method draws it,
  // on the flat surfaces the image was made of.
  if (hasShownImage()) {
    settings.method = Method::Flat;
    settings.surfaceHeight = 0.0;
  }
  const FrameComparison comparison{
      settings.view == DisplayView::Difference && settings.comparison == RenderSettings::Comparison::Method,
      settings.view == DisplayView::Difference && settings.comparison == RenderSettings::Comparison::Image,
      settings.view == DisplayView::StandardError};
  if (comparison.image && !hasReferenceImage())
    throw Error("difference view: no reference image to compare with (give one with --reference)");
  if (comparison.standardErrors && !mesh_->hasStandardErrors)
    throw Error("standard-error view: the mesh has no standard errors (a solution radview solved has them)");
  // The raised surface reaches beyond the mesh's bounds: widen the depth range to keep it.
  Camera camera = viewCamera;
  if (settings.surfaceHeight > 0.0 && methodInfo(settings.method).bezierPieces()) {
    const double lift = settings.surfaceHeight * mesh_->bounds().diagonal();
    camera.zFar += lift;
    camera.zNear = std::max(camera.zNear - lift, camera.zFar * 1e-4);
  }
  // Errors left on this context by other code (the UI) are not this pass's to report.
  while (glGetError() != GL_NO_ERROR) continue;
  targets_.resize(width, height);
  // Everything that can throw (meshes, pieces) happens before any GL state is changed.
  const bool drawNet = uploadForFrame(settings, viewCamera, comparison.method);
  timer_.begin();
  // What the shaders call world is the mesh's frame (prepareMesh): world minus origin_. The
  // product is formed in double, so only coordinates of the scene's own size reach float.
  const glm::mat4 clipFromWorld(camera.clipFromWorld(double(width) / height) *
                                glm::translate(glm::dmat4(1.0), origin_));
  // The radiosity pass's depth clamp, depth range and eye-plane clip end with the frame, also
  // when a draw throws (a tessellated draw past its limit): the viewer's panel, drawn next,
  // writes no clip distance.
  struct PassStateReset {
    ~PassStateReset() {
      glDisable(GL_DEPTH_CLAMP);
      glDisable(GL_CLIP_DISTANCE0);
      glDepthRange(0.0, 1.0);
    }
  } passStateReset;
  drawRadiosityPass(settings, camera, clipFromWorld, width, height, comparison);
  // Pass 2: the tone map or a false-colour view into the display target.
  glBindFramebuffer(GL_FRAMEBUFFER, targets_.displayFramebuffer());
  display_.draw(settings, targets_.linearTexture(),
                comparison.method || comparison.standardErrors ? targets_.comparisonTexture() : 0);
  if (settings.view == DisplayView::Difference) comparedWithImage_ = comparison.image;
  drawOverlays(settings, camera, clipFromWorld, width, height, drawNet);
  timer_.end();
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
  glDisable(GL_DEPTH_TEST);
  if (GLenum error = glGetError(); error != GL_NO_ERROR)
    throw Error("OpenGL error " + hexCode(error) + " while rendering");
}

bool MeshRenderer::uploadForFrame(const RenderSettings& settings, const Camera& viewCamera, bool compareMethod) {
  if (settings.repairTVertices != repairedDrawn_) {
    PrepareOptions options;
    options.repairTVertices = settings.repairTVertices;
    adoptMesh(prepareMesh(original_, options));
  }
  if (!trianglesUploaded_ &&
      (drawsTriangles(settings.method) || (compareMethod && drawsTriangles(settings.comparisonMethod)))) {
    uploadTriangles(drawnTriangles(*mesh_, *topology_));
    trianglesUploaded_ = true;
  }
  if (methodInfo(settings.method).bezierPieces()) uploadPatches(settings, bezierEvaluation(settings, viewCamera));
  if (settings.view == DisplayView::StandardError && !errorsUploaded_) {
    errorRaster_.setMesh(displayTriangles(*mesh_, *topology_, &Node::standardError), 0);
    errorsUploaded_ = true;
  }
  // The comparison is drawn per pixel: deferred for the C1 methods; for the quadratic one, its
  // 6-node triangles in a Bezier pass of their own unless the method's holds them.
  if (compareMethod && methodInfo(settings.comparisonMethod).bezierPieces()) {
    if (isDeferred(settings.comparisonMethod, BezierEvaluation{})) {
      const PiecesKey key = piecesKey(settings.comparisonMethod, settings);
      if (key != deferredFor_ && key != comparisonDeferredFor_) {
        uploadDeferred(prepareDeferred(mesh_, topology_, key), comparisonDeferred_, nullptr);
        comparisonDeferredFor_ = key;
      }
    } else if (patchesFor_ != PiecesKey::quadraticTriangles() &&
               comparisonPatchesFor_ != PiecesKey::quadraticTriangles()) {
      comparisonPass_.upload(quadraticTriangleVertices(*mesh_), 2);
      comparisonPatchesFor_ = PiecesKey::quadraticTriangles();
    }
  }
  const bool drawNet =
      settings.controlNet && settings.surfaceHeight > 0.0 && methodInfo(settings.method).bezierPieces();
  if (drawNet) uploadControlNet(bezierEvaluation(settings, viewCamera).surfaceHeight);
  return drawNet;
}

void MeshRenderer::drawRadiosityPass(const RenderSettings& settings, const Camera& camera,
                                     const glm::mat4& clipFromWorld, int width, int height,
                                     const FrameComparison& comparison) {
  // Pass 1: linear radiosity and depth; for a difference view against another method, that
  // method first, into the comparison target.
  glViewport(0, 0, width, height);
  // The surfaces' polygon offset under the overlays (drawOverlayDepth) grows with their depth
  // slope, which is unbounded at grazing angles: a floor seen 0.01 degree from edge-on was pushed
  // past the far plane's depth along the horizon and lost a whole row of pixels to the background
  // (tests/gl/extremes_render_test.cpp). Depth clamping keeps every fragment, and the depth range
  // ends at 0.5 so that a clamped one still passes GL_LESS against the cleared 1.0. Clamping
  // also stops near- and far-plane clipping: a surface nearer than zNear is still drawn.
  glEnable(GL_DEPTH_CLAMP);
  glDepthRange(0.0, 0.5);
  // Without near-plane clipping, what lies behind the eye is clipped at a plane just in front of
  // it (shaders/lib/eye_plane.glsl).
  // The block's std140 size: one float padded to 16 bytes.
  const glm::vec4 nearestW(float(camera.zNear * 1e-2), 0.0f, 0.0f, 0.0f);
  glNamedBufferData(eyePlane_, sizeof nearestW, &nearestW, GL_STREAM_DRAW);
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, eyePlane_);
  glEnable(GL_CLIP_DISTANCE0);
  if (comparison.method) {
    glBindFramebuffer(GL_FRAMEBUFFER, targets_.ensureComparison());
    RenderSettings perPixel = settings;
    perPixel.tessellation = 0;
    drawRadiosity(settings.comparisonMethod, perPixel, camera, clipFromWorld, width, height, true, false);
  }
  if (comparison.standardErrors) {  // linear between the nodes: Gouraud's triangles
    glBindFramebuffer(GL_FRAMEBUFFER, targets_.ensureComparison());
    const float clear[] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(targets_.comparisonFramebuffer(), GL_COLOR, 0, clear);
    glClearNamedFramebufferfi(targets_.comparisonFramebuffer(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    errorRaster_.draw(Method::Gouraud, true, clipFromWorld, errorRaster_.vertices());
  }
  glBindFramebuffer(GL_FRAMEBUFFER, targets_.linearFramebuffer());
  drawRadiosity(settings.method, settings, camera, clipFromWorld, width, height, false, false);
  if (hasShownImage()) shown_.copyTo(targets_.linearFramebuffer(), width, height);
}

void MeshRenderer::drawOverlayDepth(const RenderSettings& settings, const Camera& camera,
                                    const glm::mat4& clipFromWorld, int width, int height) {
  // A line on a surface is depth-tested against it at pixel centres off the line, where the
  // surface's depth differs from the line's by up to about half a pixel's depth change: large at
  // grazing angles. So the overlays are tested against the surfaces pushed back by their own
  // depth slope (glPolygonOffset's factor) and a few depth steps: the surfaces' depth drawn a
  // second time, colour writes off. The radiosity pass itself is not offset: there a steep
  // surface, pushed back further than a less steep one just behind it, lost to that one within
  // a pixel of their common edge: the short block's back sides showed a pixel wide along the
  // Cornell box's top face (tests/gl/edge_visibility_test.cpp).
  glBindFramebuffer(GL_FRAMEBUFFER, targets_.linearFramebuffer());
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);
  drawRadiosity(settings.method, settings, camera, clipFromWorld, width, height, false, true);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glBindFramebuffer(GL_FRAMEBUFFER, targets_.displayFramebuffer());
}

void MeshRenderer::drawOverlays(const RenderSettings& settings, const Camera& camera, const glm::mat4& clipFromWorld,
                                int width, int height, bool drawNet) {
  const bool bezierMethod = methodInfo(settings.method).bezierPieces();
  const OverlaySelection shown{settings.elementEdges,
                               bezierMethod && settings.splitLines,
                               drawNet,
                               settings.discontinuityEdges,
                               settings.tVertices,
                               settings.edgeColour};
  const bool tessellationTriangles = bezierMethod && settings.tessellationTriangles;
  if (!overlays_.draws(shown) && !tessellationTriangles) return;
  drawOverlayDepth(settings, camera, clipFromWorld, width, height);
  // Depth-tested against the surfaces, drawn over what is at their depth, not writing depth.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  overlays_.drawElementEdges(shown, clipFromWorld);
  if (tessellationTriangles)
    bezierPass_.drawTriangles(clipFromWorld, bezierEvaluation(settings, camera), kTessellationColour);
  overlays_.drawPiecesAndMarkers(shown, clipFromWorld);
  glDepthMask(GL_TRUE);
}

Image MeshRenderer::readDisplay() const {
  return {targets_.width(), targets_.height(),
          readBytePixels(targets_.displayFramebuffer(), GL_COLOR_ATTACHMENT0, targets_.width(), targets_.height())};
}

void MeshRenderer::setReferenceImage(const ReferenceImage& reference) { display_.setReferenceImage(reference); }

void MeshRenderer::setShownImage(const LinearImage& image) { shown_.set(image); }

void MeshRenderer::clearShownImage() { shown_.clear(); }

ReferenceImage MeshRenderer::readComparison() const {
  if (comparedWithImage_) return display_.referenceImage();
  if (!targets_.comparisonFramebuffer()) throw Error("no difference view has been rendered");
  ReferenceImage comparison;
  comparison.linear = true;
  comparison.path = "the comparison method";
  comparison.pixels = {
      targets_.width(), targets_.height(),
      readFloatPixels(targets_.comparisonFramebuffer(), GL_COLOR_ATTACHMENT0, targets_.width(), targets_.height())};
  return comparison;
}

LinearImage MeshRenderer::readLinear() const {
  return {targets_.width(), targets_.height(),
          readFloatPixels(targets_.linearFramebuffer(), GL_COLOR_ATTACHMENT0, targets_.width(), targets_.height())};
}

void MeshRenderer::presentToDefaultFramebuffer(int left, int width, int height) const {
  glBlitNamedFramebuffer(targets_.displayFramebuffer(), 0, 0, 0, targets_.width(), targets_.height(), left, 0,
                         left + width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

Image readDefaultFramebuffer(int width, int height) {
  return {width, height, readBytePixels(0, GL_BACK, width, height)};
}

}  // namespace radview::gl
