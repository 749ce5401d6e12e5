// Checks a viewer screenshot of the Cornell box: the panel is drawn (ImGui's window at the left
// edge, with text), and the scene is drawn beside it, not under it: the red and the green wall
// are both seen right of the panel, the picture is not one flat colour, and neither wall reaches
// the panel's edge (the box is framed whole in the columns the panel leaves).
//   check_screenshot PNG [PANEL_WIDTH]   (default 400, the panel's width at content scale 1)
#include "core/error.h"
#include "core/image.h"

#include <cstdio>
#include <cstdlib>
#include <set>

int main(int argc, char** argv) {
  if (argc != 2 && argc != 3) {
    std::fprintf(stderr, "usage: check_screenshot PNG [PANEL_WIDTH]\n");
    return 2;
  }
  const int panel = argc == 3 ? std::atoi(argv[2]) : 400;
  try {
    const radview::Image image = radview::readImage(argv[1]);
    auto pixel = [&](int x, int y) { return &image.rgba[(size_t(y) * image.width + x) * 4]; };
    auto isRed = [](const uint8_t* p) { return p[0] > 100 && p[0] > 2 * p[1] && p[0] > 2 * p[2]; };
    auto isGreen = [](const uint8_t* p) { return p[1] > 60 && p[1] > 1.2 * p[0] && p[1] > 2 * p[2]; };
    size_t red = 0, green = 0, bright = 0, atPanelEdge = 0;
    std::set<uint32_t> colours;
    for (int y = 0; y < image.height; ++y)
      for (int x = panel; x < image.width; ++x) {
        const uint8_t* p = pixel(x, y);
        colours.insert(p[0] << 16 | p[1] << 8 | p[2]);
        if (isRed(p)) ++red;
        if (isGreen(p)) ++green;  // olive under the warm light
        if (x < panel + 3 && (isRed(p) || isGreen(p))) ++atPanelEdge;
      }
    // Panel text: near-white pixels inside the panel's corner (ImGui draws text at ~(230,230,230)).
    for (int y = 10; y < 200 && y < image.height; ++y)
      for (int x = 10; x < 300 && x < panel; ++x)
        if (pixel(x, y)[0] > 200 && pixel(x, y)[1] > 200 && pixel(x, y)[2] > 200) ++bright;
    const size_t area = size_t(image.width - panel) * image.height;
    std::printf(
        "%s: %dx%d, right of the panel (x >= %d): %zu colours, red wall %.1f%%, green wall %.1f%%, wall pixels "
        "at the panel's edge %zu; panel text pixels %zu\n",
        argv[1], image.width, image.height, panel, colours.size(), 100.0 * red / area, 100.0 * green / area,
        atPanelEdge, bright);
    const bool ok = colours.size() > 200 && red > area / 50 && green > area / 50 && bright > 200 && atPanelEdge == 0;
    if (!ok) std::printf("FAILED: the screenshot does not show the Cornell box whole beside the panel\n");
    return ok ? 0 : 1;
  } catch (const radview::Error& e) {
    std::printf("FAILED: %s\n", e.what());
    return 1;
  }
}
