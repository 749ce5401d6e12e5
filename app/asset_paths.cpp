#include "app/asset_paths.h"

#include "core/error.h"

#include <filesystem>

namespace radview {

std::string bundledScenePath() {
  namespace fs = std::filesystem;
  const std::string name = "cornell_box.gltf";
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    for (const fs::path& dir : {exe.parent_path() / "assets", exe.parent_path() / "../share/radview/assets"})
      if (fs::exists(dir / name)) return (dir / name).lexically_normal().string();
  }
  const fs::path source = fs::path(RADVIEW_SOURCE_ASSETS) / name;
  if (fs::exists(source)) return source.string();
  throw Error("the bundled scene " + name + " is neither next to the radview binary nor in " RADVIEW_SOURCE_ASSETS);
}

}  // namespace radview
