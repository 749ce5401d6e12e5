// Checks a viewer screenshot of the Cornell box: the panel is drawn (ImGui's window in the top
// left corner, with text), and the scene is drawn (the red and the green wall are both seen
// and the picture is not one flat colour).
#include "core/error.h"
#include "core/image.h"

#include <cstdio>
#include <set>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: check_screenshot PNG\n");
    return 2;
  }
  try {
    const radview::Image image = radview::readImage(argv[1]);
    auto pixel = [&](int x, int y) { return &image.rgba[(size_t(y) * image.width + x) * 4]; };
    size_t red = 0, green = 0, bright = 0;
    std::set<uint32_t> colours;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const uint8_t* p = pixel(x, y);
        colours.insert(p[0] << 16 | p[1] << 8 | p[2]);
        if (p[0] > 100 && p[0] > 2 * p[1] && p[0] > 2 * p[2]) ++red;
        if (p[1] > 60 && p[1] > 1.2 * p[0] && p[1] > 2 * p[2]) ++green;  // olive under the warm light
      }
    // Panel text: near-white pixels inside the panel's corner (ImGui draws text at ~(230,230,230)).
    for (int y = 10; y < 200 && y < image.height; ++y)
      for (int x = 10; x < 300 && x < image.width; ++x)
        if (pixel(x, y)[0] > 200 && pixel(x, y)[1] > 200 && pixel(x, y)[2] > 200) ++bright;
    const size_t area = size_t(image.width) * image.height;
    std::printf("%s: %dx%d, %zu colours, red wall %.1f%%, green wall %.1f%%, panel text pixels %zu\n", argv[1],
                image.width, image.height, colours.size(), 100.0 * red / area, 100.0 * green / area, bright);
    // The panel covers part of the red wall: 1% of the window each is plenty for "drawn".
    const bool ok = colours.size() > 200 && red > area / 100 && green > area / 100 && bright > 200;
    if (!ok) std::printf("FAILED: the screenshot does not show the Cornell box and the panel\n");
    return ok ? 0 : 1;
  } catch (const radview::Error& e) {
    std::printf("FAILED: %s\n", e.what());
    return 1;
  }
}
