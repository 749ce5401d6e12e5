#include "app/viewer_input.h"

#include "app/viewer_keys.h"
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
  // GLFW's number keys are their characters' codes.
  const bool number = key >= GLFW_KEY_0 && key <= GLFW_KEY_9 && !(mods & GLFW_MOD_CONTROL);
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
  if (const ViewerKey* pressed = viewerKeyFor(key, (mods & GLFW_MOD_CONTROL) != 0)) pressed->apply(s);
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
