#include "app/viewer_input.h"

#include "interp/method_registry.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cmath>
#include <optional>

namespace radview {

namespace {

void onKey(GLFWwindow* window, int key, int, int action, int mods) {
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  if (ImGui::GetIO().WantCaptureKeyboard) return;
  ViewerState& s = *static_cast<ViewerInput*>(glfwGetWindowUserPointer(window))->state;
  if (mods & GLFW_MOD_CONTROL) {
    if (key == GLFW_KEY_Z) s.undoRequested = true;
    if (key == GLFW_KEY_S) s.writeSolutionRequested = true;
    return;
  }
  // GLFW's number keys are their characters' codes.
  const bool number = key >= GLFW_KEY_0 && key <= GLFW_KEY_9;
  if (const std::optional<Method> method = number ? methodForKey(char(key)) : std::nullopt) {
    s.settings.method = *method;
    s.gather.on = false;
    return;
  }
  if (const std::optional<RayTracer> tracer = number ? rayTracerForKey(char(key)) : std::nullopt) {
    s.gather.on = true;
    s.gather.pathTrace = *tracer == RayTracer::PathTrace;
    return;
  }
  switch (key) {
    case GLFW_KEY_V:
      s.settings.cloughTocher = s.settings.cloughTocher == CloughTocherVariant::Book
                                    ? CloughTocherVariant::AffineInvariant
                                    : CloughTocherVariant::Book;
      break;
    case GLFW_KEY_P:
      s.settings.perspectiveCorrect = !s.settings.perspectiveCorrect;
      break;
    case GLFW_KEY_E:
      s.settings.elementEdges = !s.settings.elementEdges;
      break;
    case GLFW_KEY_D:
      s.settings.discontinuityEdges = !s.settings.discontinuityEdges;
      break;
    case GLFW_KEY_T:
      s.settings.tVertices = !s.settings.tVertices;
      break;
    case GLFW_KEY_C: {
      // The views before Difference, which needs something to compare with (the panel's).
      const int cycled = static_cast<int>(gl::DisplayView::Difference);
      s.settings.view = static_cast<gl::DisplayView>((static_cast<int>(s.settings.view) + 1) % cycled);
      break;
    }
    case GLFW_KEY_L:
      s.settings.splitLines = !s.settings.splitLines;
      break;
    case GLFW_KEY_H:
      s.settings.surfaceHeight = s.settings.surfaceHeight > 0.0 ? 0.0 : 0.15;
      break;
    case GLFW_KEY_W:
      s.settings.tessellationTriangles = !s.settings.tessellationTriangles;
      break;
    case GLFW_KEY_G:
      (s.solving ? s.cancelSolveRequested : s.solveRequested) = true;
      break;
    case GLFW_KEY_N:
      s.settings.controlNet = !s.settings.controlNet;
      break;
    case GLFW_KEY_B:
      s.settings.repairTVertices = !s.settings.repairTVertices;
      break;
    case GLFW_KEY_R:
      rotateView45(s);
      break;
    case GLFW_KEY_F:
      resetCamera(s);
      break;
    case GLFW_KEY_S:
      s.screenshotRequested = true;
      break;
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD:
      s.settings.exposure += 0.5;
      break;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT:
      s.settings.exposure -= 0.5;
      break;
    case GLFW_KEY_K:
      setContinuityEditing(s, !s.editContinuity);
      break;
    case GLFW_KEY_TAB:
      s.panelShown = !s.panelShown;
      break;
    case GLFW_KEY_ESCAPE:
      glfwSetWindowShouldClose(window, GLFW_TRUE);
      break;
    default:
      break;
  }
}

void onScroll(GLFWwindow* window, double, double dy) {
  if (ImGui::GetIO().WantCaptureMouse) return;
  zoom(static_cast<ViewerInput*>(glfwGetWindowUserPointer(window))->state->camera, std::pow(0.9, dy));
}

void onDrop(GLFWwindow* window, int count, const char** paths) {
  if (count > 0) static_cast<ViewerInput*>(glfwGetWindowUserPointer(window))->droppedPath = paths[0];
}

}  // namespace

void installInput(GLFWwindow* window, ViewerInput& input) {
  glfwSetWindowUserPointer(window, &input);
  glfwSetKeyCallback(window, onKey);
  glfwSetScrollCallback(window, onScroll);
  glfwSetDropCallback(window, onDrop);
}

void handleDrag(GLFWwindow* window, ViewerInput& input) {
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window, &x, &y);
  const bool left = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  const bool right = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
                     glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
  // Editing continuity, the left button draws a stroke instead of orbiting; it is handed to
  // the loop when the button is let go.
  if (input.state->editContinuity && (left || !input.stroke.empty())) {
    if (left && (!input.stroke.empty() || !ImGui::GetIO().WantCaptureMouse)) {
      input.stroke.emplace_back(x, y);
    } else if (!left) {
      input.state->stroke = std::move(input.stroke);
      input.stroke.clear();
    }
    input.lastX = x;
    input.lastY = y;
    return;
  }
  if (!left && !right) {
    input.dragging = false;
  } else if (!input.dragging) {
    input.dragging = !ImGui::GetIO().WantCaptureMouse;
  } else {
    int width = 1, height = 1;
    glfwGetWindowSize(window, &width, &height);
    const double dx = (x - input.lastX) / height, dy = (y - input.lastY) / height;
    if (left)
      orbit(input.state->camera, dx * 3.0, dy * 3.0);
    else
      pan(input.state->camera, dx, dy);
  }
  input.lastX = x;
  input.lastY = y;
}

}  // namespace radview
