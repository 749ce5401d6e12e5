#pragma once
// The files radview ships under assets/, as the viewer's list of examples: what each one
// demonstrates, and the method and overlays that show it. A bare `radview` opens the first.
#include "interp/method_registry.h"

#include <string>
#include <vector>

namespace radview {

struct Example {
  std::string file;          // under assets/
  std::string title;         // the panel's list entry
  std::string demonstrates;  // one line, shown under the entry
  Method method = Method::Gouraud;
  bool elementEdges = false;
  bool discontinuityEdges = false;
  bool tVertices = false;
};

// In the panel's order; the first is the default.
const std::vector<Example>& bundledExamples();

// The example `file` names, or nullptr when it is none (compares file names only).
const Example* exampleForFile(const std::string& path);

// Where the example's file is: next to the radview binary (copied there by the build, or
// installed under ../share/radview/assets), else in the source tree the binary was built from.
// Throws Error when it is in neither.
std::string examplePath(const Example& example);

}  // namespace radview
