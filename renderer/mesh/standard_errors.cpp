#include "mesh/standard_errors.h"

#include "core/display_transform.h"
#include "core/error.h"

#include <algorithm>
#include <vector>

namespace radview {

StandardErrorSummary summariseStandardErrors(const RadiosityMesh& mesh) {
  if (!mesh.hasStandardErrors) throw Error("the solution has no standard errors (its solver did not estimate them)");
  // Emitters' values are their E, known exactly: their zeros would only dilute the figures.
  std::vector<char> receiving(mesh.nodes.size(), 0);
  bool anyReceiver = false;
  for (const Element& element : mesh.elements) {
    if (mesh.materials[element.material].isEmitter()) continue;
    anyReceiver = true;
    for (const auto* list : {&element.corners, &element.midEdge})
      for (uint32_t node : *list) receiving[node] = 1;
  }
  std::vector<double> errors;
  double sumB = 0.0;
  for (size_t n = 0; n < mesh.nodes.size(); ++n) {
    if (anyReceiver && !receiving[n]) continue;
    errors.push_back(luminance(mesh.nodes[n].standardError));
    sumB += luminance(mesh.nodes[n].B);
  }
  StandardErrorSummary summary;
  summary.nodes = errors.size();
  if (errors.empty()) return summary;
  summary.uncertain = size_t(std::count_if(errors.begin(), errors.end(), [](double e) { return e > 0.0; }));
  summary.meanB = sumB / double(errors.size());
  std::sort(errors.begin(), errors.end());
  auto quantile = [&](double q) { return errors[size_t(q * double(errors.size() - 1))]; };
  summary.median = quantile(0.5);
  summary.p99 = quantile(0.99);
  summary.largest = errors.back();
  return summary;
}

}  // namespace radview
