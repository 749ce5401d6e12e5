#pragma once
#include <string>

namespace radview {

// The bundled scene a bare `radview` opens: assets/cornell_box.gltf next to the executable
// (copied there by the build), else in the source tree the binary was built from.
std::string bundledScenePath();

}  // namespace radview
