// radview sample: the CPU reference interpolants at points a user names, printed at full
// double precision, one line per point, for scripts, tests and benchmarks.
#include "app/commands.h"
#include "app/viewed_file.h"
#include "core/error.h"
#include "interp/interpolant.h"
#include "interp/surface_point.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

namespace radview {

namespace {

struct PointRequest {
  std::string text;  // as given, for error messages
  bool byElement = false;
  uint32_t element = 0;
  Vec3 values{0.0};  // world position, or barycentric coordinates
};

// Entries are lines (or ';'-separated) of "x y z" or "element b0 b1 b2"; '#' starts a comment.
std::vector<PointRequest> parsePoints(const std::string& spec, size_t elementCount) {
  std::string text;
  std::string source = "--points";
  if (spec == "-") {
    std::stringstream ss;
    ss << std::cin.rdbuf();
    text = ss.str();
    source = "standard input";
  } else if (std::ifstream in(spec); in && spec.find(' ') == std::string::npos && spec.find(';') == std::string::npos) {
    std::stringstream ss;
    ss << in.rdbuf();
    text = ss.str();
    source = spec;
  } else {
    text = spec;
  }
  std::vector<PointRequest> out;
  std::stringstream lines(text);
  size_t lineNumber = 0;
  for (std::string line; std::getline(lines, line);) {
    ++lineNumber;
    std::stringstream entries(line.substr(0, line.find('#')));
    for (std::string entry; std::getline(entries, entry, ';');) {
      std::stringstream fields(entry);
      std::vector<std::string> words;
      for (std::string w; fields >> w;) words.push_back(w);
      if (words.empty()) continue;
      const std::string where = source + " line " + std::to_string(lineNumber) + ", '" + entry + "'";
      std::vector<double> numbers;
      for (const std::string& w : words) {
        size_t used = 0;
        double v = 0.0;
        try {
          v = std::stod(w, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used != w.size() || !std::isfinite(v)) throw Error(where + ": '" + w + "' is not a finite number");
        numbers.push_back(v);
      }
      PointRequest request;
      request.text = entry;
      if (numbers.size() == 3) {
        request.values = {numbers[0], numbers[1], numbers[2]};
      } else if (numbers.size() == 4) {
        if (numbers[0] < 0 || numbers[0] != std::floor(numbers[0]) || numbers[0] >= double(elementCount))
          throw Error(where + ": no element " + words[0] + " (the mesh has " + std::to_string(elementCount) +
                      " elements, numbered from 0)");
        request.byElement = true;
        request.element = static_cast<uint32_t>(numbers[0]);
        request.values = {numbers[1], numbers[2], numbers[3]};
        if (std::abs(numbers[1] + numbers[2] + numbers[3] - 1.0) > 1e-9)
          throw Error(where + ": barycentric coordinates must sum to 1");
      } else {
        throw Error(where + ": expected 'x y z' or 'element b0 b1 b2'");
      }
      out.push_back(request);
    }
  }
  if (out.empty()) throw Error(source + ": no points given");
  return out;
}

}  // namespace

int runSample(const SampleOptions& options) {
  const Method method = methodFromName(options.method);
  InterpolantOptions interpolantOptions;
  if (options.diagonal != "02" && options.diagonal != "13")
    throw Error("--diagonal '" + options.diagonal + "': expected 02 or 13");
  interpolantOptions.diagonal = options.diagonal == "13" ? QuadDiagonal::D13 : QuadDiagonal::D02;
  interpolantOptions.cloughTocher = cloughTocherVariantFromName(options.variant);
  interpolantOptions.useStoredGradients = !options.estimateGradients;

  const ViewedFile viewed = openForViewing(options.file, options.elementSize);
  const RadiosityMesh& mesh = viewed.mesh;
  const std::vector<PointRequest> requests = parsePoints(options.points, mesh.elements.size());
  const double maxDistance = options.maxDistance >= 0.0 ? options.maxDistance : 1e-3 * mesh.bounds().diagonal();
  // Every point is placed before anything is printed, so a bad one leaves no partial output.
  std::vector<SurfacePoint> points;
  for (const PointRequest& request : requests) {
    SurfacePoint point;
    if (request.byElement) {
      point.element = request.element;
      point.x = pointFromBarycentric(mesh, request.element, request.values);
    } else {
      point = nearestSurfacePoint(mesh, request.values);
      if (point.distance > maxDistance)
        throw Error("point '" + request.text + "' is off every surface: the nearest element (" +
                    std::to_string(point.element) + ") is " + std::to_string(point.distance) +
                    " away, more than --max-distance " + std::to_string(maxDistance));
    }
    points.push_back(point);
  }
  const std::unique_ptr<Interpolant> interpolant = makeInterpolant(mesh, method, interpolantOptions);

  std::printf("# radview sample %s --method %s: element x y z distance B_r B_g B_b "
              "dBr/dx dBr/dy dBr/dz dBg/dx dBg/dy dBg/dz dBb/dx dBb/dy dBb/dz\n",
              options.file.c_str(), options.method.c_str());
  for (const SurfacePoint& point : points) {
    const Sample s = interpolant->evaluate(point.element, point.x);
    std::printf("%u %.17g %.17g %.17g %.17g %.17g %.17g %.17g", point.element, point.x.x, point.x.y, point.x.z,
                point.distance, s.B.r, s.B.g, s.B.b);
    for (const Vec3& g : s.gradient) std::printf(" %.17g %.17g %.17g", g.x, g.y, g.z);
    std::printf("\n");
  }
  return 0;
}

}  // namespace radview
