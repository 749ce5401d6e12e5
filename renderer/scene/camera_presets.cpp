#include "scene/camera_presets.h"

#include "core/error.h"
#include "core/strings.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace radview {

std::vector<std::string> cameraPresetNames() {
  return {"file", "front", "back", "left", "right", "top", "bottom", "iso"};
}

namespace {

// A camera looking at the bounds' centre from `direction`, far enough for the bounding sphere
// to fill the vertical field of view.
Camera looking(const Bounds& bounds, Vec3 direction, Vec3 up) {
  Camera c;
  c.yfov = glm::radians(40.0);
  const double radius = std::max(0.5 * bounds.diagonal(), 1e-6);
  const double distance = radius / std::sin(0.5 * c.yfov);
  c.target = bounds.center();
  c.eye = c.target - glm::normalize(direction) * distance;
  c.up = up;
  return c;
}

bool parseVec3(const std::string& text, Vec3& out) {
  std::istringstream is(text);
  char comma1 = 0, comma2 = 0;
  if (!(is >> out.x >> comma1 >> out.y >> comma2 >> out.z) || comma1 != ',' || comma2 != ',') return false;
  is >> std::ws;
  return is.eof() && isFinite(out);
}

Camera fromEyeTargetUp(const std::string& spec) {
  std::vector<std::string> parts;
  std::stringstream ss(spec);
  for (std::string part; std::getline(ss, part, '/');) parts.push_back(part);
  Camera c;
  if ((parts.size() != 2 && parts.size() != 3) || !parseVec3(parts[0], c.eye) || !parseVec3(parts[1], c.target) ||
      (parts.size() == 3 && !parseVec3(parts[2], c.up)))
    throw Error("--camera '" + spec + "': expected a preset or ex,ey,ez/tx,ty,tz[/ux,uy,uz]");
  if (glm::length(c.target - c.eye) <= 0.0) throw Error("--camera '" + spec + "': eye and target coincide");
  if (glm::length(glm::cross(c.target - c.eye, c.up)) <= 1e-12 * glm::length(c.target - c.eye) * glm::length(c.up))
    throw Error("--camera '" + spec + "': up is parallel to the view direction");
  return c;
}

}  // namespace

Camera cameraFromSpec(const std::string& spec, const Bounds& bounds, const std::vector<SceneCamera>& fileCameras) {
  const std::string name = spec.empty() ? (fileCameras.empty() ? "front" : "file") : spec;
  Camera c;
  if (name == "file") {
    if (fileCameras.empty()) throw Error("--camera file: the file has no camera");
    const SceneCamera& s = fileCameras.front();
    c.eye = s.eye;
    c.target = s.target;
    c.up = s.up;
    c.yfov = s.yfov;
  } else if (name == "front") {
    c = looking(bounds, {0, 0, -1}, {0, 1, 0});
  } else if (name == "back") {
    c = looking(bounds, {0, 0, 1}, {0, 1, 0});
  } else if (name == "left") {
    c = looking(bounds, {1, 0, 0}, {0, 1, 0});
  } else if (name == "right") {
    c = looking(bounds, {-1, 0, 0}, {0, 1, 0});
  } else if (name == "top") {
    c = looking(bounds, {0, -1, 0}, {0, 0, -1});
  } else if (name == "bottom") {
    c = looking(bounds, {0, 1, 0}, {0, 0, 1});
  } else if (name == "iso") {
    c = looking(bounds, {-1, -1, -1}, {0, 1, 0});
  } else if (name.find('/') != std::string::npos) {
    c = fromEyeTargetUp(name);
  } else {
    throw Error("--camera '" + spec + "': unknown preset (use one of " + joined(cameraPresetNames()) +
                ", or ex,ey,ez/tx,ty,tz[/ux,uy,uz])");
  }
  fitClipPlanes(c, bounds);
  return c;
}

}  // namespace radview
