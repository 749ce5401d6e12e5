#pragma once
// The ways a user names a camera: one of the file's cameras, a preset framing the scene's
// bounds, or "eye/target/up".
#include "core/camera.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace radview {

// Names accepted by cameraFromSpec, for --help: "file" (the file's first camera), "front",
// "back", "left", "right", "top", "bottom", "iso".
std::vector<std::string> cameraPresetNames();

// The camera a user asked for: a preset name, or "ex,ey,ez/tx,ty,tz[/ux,uy,uz]". An empty
// spec means "file" when the file has a camera, else "front". Throws Error for a bad spec.
Camera cameraFromSpec(const std::string& spec, const Bounds& bounds, const std::vector<SceneCamera>& fileCameras);

}  // namespace radview
