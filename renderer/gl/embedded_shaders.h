#pragma once
#include <map>
#include <string>

namespace radview::gl {

// shaders/ as embedded at build time, keyed by path relative to shaders/ ("mesh.vert").
const std::map<std::string, std::string>& embeddedShaders();

}  // namespace radview::gl
