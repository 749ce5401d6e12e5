#pragma once
// The viewer's keys, in one table. The number keys pick the registry's methods and ray tracers
// (interp/method_registry.h); the others are listed here with what they do. The key handler
// (viewer_input.cpp), the panel's and --help's list (shortcutHelp) and README's table of keys
// (`radview keys`, which writes it) all read it.
#include "app/viewer_panel.h"

#include <functional>
#include <string>
#include <vector>

namespace radview {

struct ViewerKey {
  std::vector<int> codes;  // the GLFW key codes that press it (+ and the keypad's +)
  bool control = false;    // with Ctrl held
  std::string label;       // "E", "Ctrl+Z": as the lists show it
  std::string action;      // "element edges": what it does
  std::function<void(ViewerState&)> apply;
};

const std::vector<ViewerKey>& viewerKeys();
// The key a press with these GLFW code and Ctrl state is, if any.
const ViewerKey* viewerKeyFor(int code, bool control);
// Every key, the mouse and a dropped file as plain text, wrapped: the panel's list and --help's.
const std::string& shortcutHelp();
// Every key as a Markdown table (key | what it does): the number keys first, then the table's,
// then the mouse and a dropped file.
std::string keysMarkdown();

}  // namespace radview
