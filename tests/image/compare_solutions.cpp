// Compares a bundled solution with one the solver makes now from the same command: the same
// mesh (nodes, elements, discontinuity edges) and the same radiosities, up to what a rare ray
// that Embree decides the other way on another CPU can change (at most 0.1 % of the nodes off by
// more than 1e-3 of the largest value). Says which to rerun when they differ.
//   compare_solutions BUNDLED FRESH SCRIPT
#include "core/error.h"
#include "import/load_file.h"

#include <algorithm>
#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: compare_solutions BUNDLED FRESH SCRIPT\n");
    return 2;
  }
  try {
    const radview::RadiosityMesh bundled = radview::loadFile(argv[1]).mesh, fresh = radview::loadFile(argv[2]).mesh;
    std::printf("%s: %zu nodes, %zu elements, %zu discontinuity edges; the solver now: %zu, %zu, %zu\n", argv[1],
                bundled.nodes.size(), bundled.elements.size(), bundled.discontinuities.size(), fresh.nodes.size(),
                fresh.elements.size(), fresh.discontinuities.size());
    bool same = bundled.nodes.size() == fresh.nodes.size() && bundled.elements.size() == fresh.elements.size() &&
                bundled.discontinuities.size() == fresh.discontinuities.size() &&
                bundled.hasStandardErrors == fresh.hasStandardErrors;
    for (size_t e = 0; same && e < bundled.elements.size(); ++e)
      same = bundled.elements[e].corners == fresh.elements[e].corners;
    if (same) {
      double largest = 0.0;
      for (const radview::Node& n : bundled.nodes) largest = std::max({largest, n.B.r, n.B.g, n.B.b});
      size_t off = 0;
      double worst = 0.0;
      for (size_t i = 0; i < bundled.nodes.size(); ++i) {
        const radview::Rgb d = glm::abs(bundled.nodes[i].B - fresh.nodes[i].B);
        const double difference = std::max({d.r, d.g, d.b});
        worst = std::max(worst, difference);
        if (difference > 1e-3 * largest) ++off;
      }
      std::printf("largest difference %.3g of the largest value; %zu nodes off by more than 1e-3 of it\n",
                  worst / largest, off);
      same = off * 1000 <= bundled.nodes.size();
    }
    if (!same) std::printf("FAILED: %s is not what the solver makes now: rerun %s\n", argv[1], argv[3]);
    return same ? 0 : 1;
  } catch (const radview::Error& e) {
    std::printf("FAILED: %s\n", e.what());
    return 1;
  }
}
