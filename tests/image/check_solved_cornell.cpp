// Checks what a bare `radview` renders where no display exists: the bundled solved Cornell box
// (assets/cornell_box_solved.glb) at the viewer's default 1280x800 from the file's camera, with
// what only a global solution has: a lit ceiling (no direct light reaches it), the short block's
// shadow on the floor, and the red wall's light on the tall block's face that looks at it.
//   check_solved_cornell PNG
#include "core/error.h"
#include "core/image.h"

#include <cstdio>

namespace {

struct Mean {
  double r = 0, g = 0, b = 0;
  double luminance() const { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }
};

// The mean colour of the 9x9 pixels around (x, y).
Mean around(const radview::Image& image, int x, int y) {
  Mean m;
  int n = 0;
  for (int j = y - 4; j <= y + 4; ++j)
    for (int i = x - 4; i <= x + 4; ++i) {
      const uint8_t* p = &image.rgba[(size_t(j) * image.width + i) * 4];
      m.r += p[0], m.g += p[1], m.b += p[2];
      ++n;
    }
  m.r /= n, m.g /= n, m.b /= n;
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: check_solved_cornell PNG\n");
    return 2;
  }
  try {
    const radview::Image image = radview::readImage(argv[1]);
    if (image.width != 1280 || image.height != 800) {
      std::printf("FAILED: %s is %dx%d, not the viewer's 1280x800\n", argv[1], image.width, image.height);
      return 1;
    }
    const Mean ceiling = around(image, 640, 50);
    // The shadow is sampled well inside it, right of the short block's front corner: its
    // penumbra towards the green wall is mottled by the solution's noise (about 0.6 of the open
    // floor at 900,728, 0.5 here).
    const Mean shadow = around(image, 870, 750), openFloor = around(image, 700, 772);
    const Mean facingRedWall = around(image, 470, 450), facingViewer = around(image, 560, 450);
    std::printf(
        "%s: ceiling luminance %.0f; floor %.0f in the short block's shadow, %.0f in the open; tall "
        "block's face towards the red wall R/G %.2f, its front face %.2f\n",
        argv[1], ceiling.luminance(), shadow.luminance(), openFloor.luminance(), facingRedWall.r / facingRedWall.g,
        facingViewer.r / facingViewer.g);
    bool ok = true;
    if (ceiling.luminance() < 40) ok = false, std::printf("FAILED: the ceiling is dark: no interreflection\n");
    if (shadow.luminance() > 0.6 * openFloor.luminance()) ok = false, std::printf("FAILED: no shadow on the floor\n");
    if (facingRedWall.r < 2.0 * facingRedWall.g ||
        facingRedWall.r / facingRedWall.g < 1.5 * facingViewer.r / facingViewer.g)
      ok = false, std::printf("FAILED: no red bleeding onto the tall block\n");
    return ok ? 0 : 1;
  } catch (const radview::Error& e) {
    std::printf("FAILED: %s\n", e.what());
    return 1;
  }
}
