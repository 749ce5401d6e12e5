#pragma once
// The viewer's state and its ImGui panel. ImGui lives only in app/.
#include "app/viewed_file.h"
#include "core/camera.h"
#include "gl/mesh_renderer.h"

#include <string>

namespace radview {

struct ViewerState {
  ViewedFile viewed;
  Camera camera;
  Camera homeCamera;  // the camera the file opened with ('F' returns to it)
  gl::RenderSettings settings;
  std::string status;        // last message: file opened, screenshot written, error
  std::string pathToOpen;    // panel's "open" field
  bool openRequested = false;
  bool screenshotRequested = false;
  int rollSteps = 0;         // 45-degree view rotations applied (fig. 9.8)
  double cpuFrameMs = 0.0;
  double gpuFrameMs = 0.0;
  size_t triangles = 0;
  gl::TessellationStatistics tessellation;  // of the last quadratic or C1 frame
  std::string referencePath;        // panel's reference image field (difference view)
  bool referenceRequested = false;  // load referencePath as the reference image
  std::string difference;           // the difference view's statistics, when the sizes allow
  // The background solve (scenes only): requests from the panel, and what it reports.
  bool solveRequested = false;
  bool cancelSolveRequested = false;
  bool solving = false;
  std::string solveStatus;
  std::string solutionPath;            // where "Write solution" writes the mesh shown
  bool writeSolutionRequested = false;
};

void rotateView45(ViewerState& state);
void resetCamera(ViewerState& state);

// Keyboard shortcuts, as listed in the panel and in --help.
const char* shortcutHelp();

void drawPanel(ViewerState& state);

}  // namespace radview
