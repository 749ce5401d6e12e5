#pragma once
// The viewer's keyboard and mouse: number keys pick a method (interp/method_registry.h), letters
// toggle settings or ask for work (the loop in viewer.cpp does it), the mouse orbits, pans and
// zooms, a dropped file is opened. Keys and mouse go to the panel first when it wants them.
#include "app/viewer_panel.h"

#include <string>
#include <utility>
#include <vector>

struct GLFWwindow;

namespace radview {

struct ViewerInput {
  ViewerState* state = nullptr;
  std::string droppedPath;  // set by a drop, taken by the loop
  double lastX = 0.0, lastY = 0.0;
  bool dragging = false;
  std::vector<std::pair<double, double>> stroke;  // the left button's path while editing continuity
};

// Sets `input` as the window's user pointer and the key, scroll and drop callbacks; before
// ImGui's, which chain to them.
void installInput(GLFWwindow* window, ViewerInput& input);
// Mouse drags, polled once a frame: left orbits (or, editing continuity, strokes across
// edges), right or middle pans.
void handleDrag(GLFWwindow* window, ViewerInput& input);

}  // namespace radview
