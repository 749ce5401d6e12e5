#pragma once
// The viewer's state and its ImGui panel. ImGui lives only in app/.
#include "core/camera.h"
#include "edit/continuity_edit.h"
#include "gather/background_gather.h"
#include "gl/mesh_renderer.h"
#include "interp/interpolant.h"
#include "solve/viewed_file.h"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace radview {

// The final gather (C&W §9.3.1) in the window, in place of the GL method (which is drawn while
// the view moves): what the panel and the command line set, and what the gather reports.
struct GatherControls {
  bool on = false;
  bool pathTrace = false;                // on: the path tracer's true image instead of the final gather
  Method interpolant = Method::Gouraud;  // B^ under the integral of eq. 9.9
  int emitterSamples = 1;                // shadow rays per pixel per pass
  uint64_t seed = 1;
  int targetSpp = 1024;  // it stops at this many samples per pixel
  bool paused = false;
  GatherProgress progress;
};

struct ViewerState {
  ViewedFile viewed;
  Camera camera;
  Camera homeCamera;  // the camera the file opened with ('F' returns to it)
  gl::RenderSettings settings;
  std::string status;      // last message: file opened, screenshot written, error
  std::string pathToOpen;  // panel's "open" field
  bool openRequested = false;
  bool screenshotRequested = false;
  int rollSteps = 0;  // 45-degree view rotations applied (fig. 9.8)
  double cpuFrameMs = 0.0;
  double gpuFrameMs = 0.0;
  size_t triangles = 0;
  Method drawnMethod = Method::Gouraud;  // what the last frame drew: settings.method, or Gouraud while its pieces are set up
  size_t tVertexCount = 0;  // the drawn mesh's (C&W §9.2), as the renderer found them
  gl::TessellationStatistics tessellation;  // of the last quadratic or C1 frame
  std::string referencePath;                // panel's reference image field (difference view)
  bool referenceRequested = false;          // load referencePath as the reference image
  std::string difference;                   // the difference view's statistics, when the sizes allow
  // The background solve (scenes only): requests from the panel, and what it reports.
  bool solveRequested = false;
  bool cancelSolveRequested = false;
  bool solving = false;
  bool solveForView = false;  // the solve's subdivision meshes for the current view (C&W §9.3)
  std::string solveStatus;
  std::string solutionPath;  // where "Write solution" writes the mesh shown
  bool writeSolutionRequested = false;
  GatherControls gather;
  // The panel sits at the window's left edge, full height; the scene is framed in the rest.
  bool panelShown = true;                            // Tab hides and shows it
  float panelWidth = 0.0f;                           // in window coordinates, as last drawn; 0 when hidden or collapsed
  const struct Example* requestedExample = nullptr;  // opening from the list: applied once it opens
  // Editing continuity (Salesin et al. 1992): in edit mode a left click or drag retags the
  // element edges it passes (C1 -> C0 -> C-1), undo steps back.
  bool editContinuity = false;
  std::vector<std::pair<double, double>> stroke;  // a finished click or drag, window coordinates
  bool undoRequested = false;
  bool quitRequested = false;  // Esc: the loop closes the window
  size_t undoSteps = 0;
  std::optional<EdgeRef> pickedEdge;  // the last edge retagged, described in the panel
  std::string pickedDescription;
};

void rotateView45(ViewerState& state);
// Edit mode on also shows the element and discontinuity edges, which it is about.
void setContinuityEditing(ViewerState& state, bool on);
void resetCamera(ViewerState& state);

// The panel's width before scaling to the monitor's content scale.
constexpr float kPanelWidth = 400.0f;

void drawPanel(ViewerState& state);

}  // namespace radview
