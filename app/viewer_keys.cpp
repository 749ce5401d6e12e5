#include "app/viewer_keys.h"

#include "core/strings.h"
#include "interp/method_registry.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace radview {

namespace {

template <typename T>
void toggle(T& value) {
  value = !value;
}

// The mouse and a dropped file, after the keys.
const char* const kMouse[][2] = {
    {"left drag", "orbit (editing continuity: retag the edges it crosses)"},
    {"right or middle drag", "pan"},
    {"wheel", "zoom"},
    {"drop a file", "open it (.gltf, .glb, .ply, .obj)"},
};

// "normal, value, ...": the views the C key steps through.
std::string cycledViewNames() {
  std::vector<std::string> names;
  for (const gl::DisplayViewInfo& info : gl::displayViewRegistry())
    if (info.cycled) names.push_back(info.name);
  return joined(names);
}

}  // namespace

const std::vector<ViewerKey>& viewerKeys() {
  using S = ViewerState;
  static const std::vector<ViewerKey> keys = {
      {{GLFW_KEY_V}, false, "V", "Clough-Tocher's variant: the book's or affine-invariant",
       [](S& s) {
         s.settings.cloughTocher = s.settings.cloughTocher == CloughTocherVariant::Book
                                       ? CloughTocherVariant::AffineInvariant
                                       : CloughTocherVariant::Book;
       }},
      {{GLFW_KEY_P}, false, "P", "Gouraud perspective-correct or in screen space",
       [](S& s) { toggle(s.settings.perspectiveCorrect); }},
      {{GLFW_KEY_C}, false, "C", "the next view: " + cycledViewNames(),
       [](S& s) { s.settings.view = gl::nextCycledView(s.settings.view, s.viewed.mesh.hasStandardErrors); }},
      {{GLFW_KEY_E}, false, "E", "element edges", [](S& s) { toggle(s.settings.elementEdges); }},
      {{GLFW_KEY_D}, false, "D", "discontinuity edges", [](S& s) { toggle(s.settings.discontinuityEdges); }},
      {{GLFW_KEY_T}, false, "T", "T-vertices", [](S& s) { toggle(s.settings.tVertices); }},
      {{GLFW_KEY_B}, false, "B", "repair T-vertices (triangulate through them)",
       [](S& s) { toggle(s.settings.repairTVertices); }},
      {{GLFW_KEY_L}, false, "L", "split lines of the C1 pieces", [](S& s) { toggle(s.settings.splitLines); }},
      {{GLFW_KEY_W}, false, "W", "tessellation triangles", [](S& s) { toggle(s.settings.tessellationTriangles); }},
      {{GLFW_KEY_H}, false, "H", "radiosity surface (fig. 9.13)",
       [](S& s) { s.settings.surfaceHeight = s.settings.surfaceHeight > 0.0 ? 0.0 : 0.15; }},
      {{GLFW_KEY_N}, false, "N", "its control net", [](S& s) { toggle(s.settings.controlNet); }},
      {{GLFW_KEY_K}, false, "K", "edit continuity: click or drag across edges, C1 -> C0 -> C-1",
       [](S& s) { setContinuityEditing(s, !s.editContinuity); }},
      {{GLFW_KEY_Z}, true, "Ctrl+Z", "undo an edit", [](S& s) { s.undoRequested = true; }},
      {{GLFW_KEY_S}, true, "Ctrl+S", "write the solution", [](S& s) { s.writeSolutionRequested = true; }},
      {{GLFW_KEY_G}, false, "G", "solve the scene in the background (or cancel the solve)",
       [](S& s) { (s.solving ? s.cancelSolveRequested : s.solveRequested) = true; }},
      {{GLFW_KEY_R}, false, "R", "rotate the view 45 degrees clockwise (fig. 9.8)", [](S& s) { rotateView45(s); }},
      {{GLFW_KEY_F}, false, "F", "reset the camera", [](S& s) { resetCamera(s); }},
      {{GLFW_KEY_EQUAL, GLFW_KEY_KP_ADD}, false, "+", "exposure up half a stop",
       [](S& s) { s.settings.exposure += 0.5; }},
      {{GLFW_KEY_MINUS, GLFW_KEY_KP_SUBTRACT}, false, "-", "exposure down half a stop",
       [](S& s) { s.settings.exposure -= 0.5; }},
      {{GLFW_KEY_S}, false, "S", "screenshot (PNG in the current folder)", [](S& s) { s.screenshotRequested = true; }},
      {{GLFW_KEY_TAB}, false, "Tab", "hide or show the panel", [](S& s) { toggle(s.panelShown); }},
      {{GLFW_KEY_ESCAPE}, false, "Esc", "quit", [](S& s) { s.quitRequested = true; }},
  };
  return keys;
}

const ViewerKey* viewerKeyFor(int code, bool control) {
  for (const ViewerKey& key : viewerKeys())
    if (key.control == control)
      for (int c : key.codes)
        if (c == code) return &key;
  return nullptr;
}

const std::string& shortcutHelp() {
  static const std::string help = [] {
    std::vector<std::string> items;
    for (const MethodInfo& info : methodRegistry()) items.push_back(std::string(1, info.key) + " " + info.label);
    for (const RayTracerInfo& info : rayTracerRegistry())
      items.push_back(std::string(1, info.key) + " " + info.label + " (converging)");
    for (const ViewerKey& key : viewerKeys()) items.push_back(key.label + " " + key.action);
    std::string text = "Viewer keys:", line;
    for (size_t i = 0; i < items.size(); ++i) {
      const std::string item = items[i] + (i + 1 < items.size() ? "," : ".");
      if (!line.empty() && line.size() + 1 + item.size() > 100) {
        text += "\n" + line;
        line.clear();
      }
      line += (line.empty() ? "" : " ") + item;
    }
    text += "\n" + line + "\nMouse:";
    for (const auto& [what, does] : kMouse) text += std::string(" ") + what + ": " + does + ";";
    text.back() = '.';
    return text;
  }();
  return help;
}

std::string keysMarkdown() {
  std::string table = "| key | what it does |\n|---|---|\n";
  for (const MethodInfo& info : methodRegistry())
    table += std::string("| `") + info.key + "` | " + info.label + " (" + info.section + ") |\n";
  for (const RayTracerInfo& info : rayTracerRegistry())
    table += std::string("| `") + info.key + "` | " + info.label + ", converging as it runs (" + info.section + ") |\n";
  for (const ViewerKey& key : viewerKeys()) table += "| `" + key.label + "` | " + key.action + " |\n";
  for (const auto& [what, does] : kMouse) table += std::string("| ") + what + " | " + does + " |\n";
  return table;
}

}  // namespace radview
