// The command-line side of the numerical-extremes tests (tests/image/extremes_cli_test.sh):
//   extreme_box_tool write PLACEMENT FILE.glb   the closed box of tests/extreme_scenes.h as a solution file
//   extreme_box_tool camera PLACEMENT VIEW      an inside view as radview's --camera eye/target/up
//   extreme_box_tool check FILE.exr             every pixel finite and covered, or exit 1
// PLACEMENT and VIEW are indices into extremePlacements() and insideViews().
#include "core/error.h"
#include "core/image.h"
#include "mesh/solution_file.h"
#include "tests/extreme_scenes.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace {

int usage() {
  std::fprintf(stderr, "usage: extreme_box_tool write PLACEMENT FILE | camera PLACEMENT VIEW | check EXR\n");
  return 2;
}

std::string vec(const radview::Vec3& v) {
  char text[128];
  std::snprintf(text, sizeof text, "%.17g,%.17g,%.17g", v.x, v.y, v.z);
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace radview;
  if (argc < 3) return usage();
  const std::string command = argv[1];
  try {
    if (command == "write" && argc == 4) {
      writeSolution(test::extremeBox(test::extremePlacements().at(std::stoul(argv[2]))), argv[3]);
      return 0;
    }
    if (command == "camera" && argc == 4) {
      const test::Placement placement = test::extremePlacements().at(std::stoul(argv[2]));
      const test::NamedView view = test::insideViews().at(std::stoul(argv[3]));
      std::printf("%s/%s/%s\n", vec(placement.place(view.eye)).c_str(), vec(placement.place(view.target)).c_str(),
                  vec(view.up).c_str());
      return 0;
    }
    if (command == "check" && argc == 3) {
      const LinearImage image = readReferenceImage(argv[2]).pixels;
      size_t nonFinite = 0, uncovered = 0;
      for (size_t i = 0; i < image.rgba.size(); i += 4) {
        const float* p = &image.rgba[i];
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]) || !std::isfinite(p[3]))
          ++nonFinite;
        else if (p[3] == 0.0f)
          ++uncovered;
      }
      std::printf("%s: %dx%d, %zu pixels not finite, %zu uncovered\n", argv[2], image.width, image.height, nonFinite,
                  uncovered);
      return nonFinite + uncovered == 0 && !image.rgba.empty() ? 0 : 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "extreme_box_tool: %s\n", e.what());
    return 1;
  }
  return usage();
}
