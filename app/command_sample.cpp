// radview sample: the CPU reference interpolants at points a user names, one line per point,
// each number the shortest text that reads back as the same double, for scripts, tests and
// benchmarks. Points are located through a spatial index and evaluated on every core, so a
// million of them on a million elements take seconds.
#include "app/commands.h"
#include "app/solve_progress_bar.h"
#include "core/atomic_file.h"
#include "core/camera.h"
#include "core/error.h"
#include "core/npy_array.h"
#include "core/parallel_for.h"
#include "core/strings.h"
#include "interp/interpolant.h"
#include "interp/point_sampling.h"
#include "scene/camera_presets.h"
#include "solve/viewed_file.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string_view>

namespace radview {

namespace {

struct PointRequest {
  std::string_view entry;  // as given, for error messages (text input)
  size_t row = 0;          // the row, from a .npy array (entry empty)
  PointQuery query;
};

std::string readAll(std::istream& in) {
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Entries are lines (or ';'-separated) of "x y z" or "element b0 b1 b2"; '#' starts a comment.
// The requests point into `text`.
std::vector<PointRequest> parsePoints(std::string_view text, const std::string& source, size_t elementCount) {
  std::vector<PointRequest> out;
  size_t lineNumber = 0;
  for (size_t lineStart = 0; lineStart < text.size();) {
    const size_t lineEnd = std::min(text.find('\n', lineStart), text.size());
    std::string_view line = text.substr(lineStart, lineEnd - lineStart);
    lineStart = lineEnd + 1;
    ++lineNumber;
    line = line.substr(0, line.find('#'));
    for (size_t entryStart = 0; entryStart <= line.size();) {
      const size_t entryEnd = std::min(line.find(';', entryStart), line.size());
      const std::string_view entry = line.substr(entryStart, entryEnd - entryStart);
      entryStart = entryEnd + 1;
      const auto where = [&] {
        return source + " line " + std::to_string(lineNumber) + ", '" + std::string(entry) + "'";
      };
      std::array<double, 4> numbers{};
      std::array<std::string_view, 4> words;
      size_t count = 0;
      for (size_t i = 0; i < entry.size();) {
        while (i < entry.size() && isBlank(entry[i])) ++i;
        size_t j = i;
        while (j < entry.size() && !isBlank(entry[j])) ++j;
        if (j > i) {
          const std::string_view word = entry.substr(i, j - i);
          const std::optional<double> v = parseFiniteNumber(word);
          if (!v) throw Error(where() + ": '" + std::string(word) + "' is not a finite number");
          if (count == 4) throw Error(where() + ": expected 'x y z' or 'element b0 b1 b2'");
          words[count] = word;
          numbers[count++] = *v;
        }
        i = j;
      }
      if (count == 0) continue;
      PointRequest request;
      request.entry = entry;
      if (count == 3) {
        request.query.values = {numbers[0], numbers[1], numbers[2]};
      } else if (count == 4) {
        if (numbers[0] < 0 || numbers[0] != std::floor(numbers[0]) || numbers[0] >= double(elementCount))
          throw Error(where() + ": no element " + std::string(words[0]) + " (the mesh has " +
                      std::to_string(elementCount) + " elements, numbered from 0)");
        request.query.element = static_cast<uint32_t>(numbers[0]);
        request.query.values = {numbers[1], numbers[2], numbers[3]};
        if (std::abs(numbers[1] + numbers[2] + numbers[3] - 1.0) > 1e-9)
          throw Error(where() + ": barycentric coordinates must sum to 1");
      } else {
        throw Error(where() + ": expected 'x y z' or 'element b0 b1 b2'");
      }
      out.push_back(request);
    }
  }
  if (out.empty()) throw Error(source + ": no points given");
  return out;
}

// Rows of a .npy array (core/npy_array.h): x y z, or element b0 b1 b2, as the text's entries.
std::vector<PointRequest> pointsFromNpy(const std::string& path, size_t elementCount) {
  const NpyMatrix rows = readNpy(path);
  if (rows.columns != 3 && rows.columns != 4)
    throw Error(path, "has " + std::to_string(rows.columns) +
                          " columns; expected 3 (x y z) or 4 (element b0 b1 b2)");
  if (rows.rows == 0) throw Error(path, "no points given");
  std::vector<PointRequest> out(rows.rows);
  for (size_t i = 0; i < rows.rows; ++i) {
    const auto where = [&] { return "row " + std::to_string(i); };
    for (size_t k = 0; k < rows.columns; ++k)
      if (!std::isfinite(rows.at(i, k))) throw Error(path, where() + " holds a number that is not finite");
    PointRequest& request = out[i];
    request.row = i;
    if (rows.columns == 3) {
      request.query.values = {rows.at(i, 0), rows.at(i, 1), rows.at(i, 2)};
      continue;
    }
    const double element = rows.at(i, 0);
    if (element < 0 || element != std::floor(element) || element >= double(elementCount))
      throw Error(path, where() + ": no element " + std::to_string(element) + " (the mesh has " +
                            std::to_string(elementCount) + " elements, numbered from 0)");
    request.query.element = uint32_t(element);
    request.query.values = {rows.at(i, 1), rows.at(i, 2), rows.at(i, 3)};
    // float32 coordinates sum to 1 only within float32's rounding.
    const double tolerance = rows.itemBytes == 4 ? 1e-6 : 1e-9;
    const Vec3& b = request.query.values;
    if (std::abs(b.x + b.y + b.z - 1.0) > tolerance)
      throw Error(path, where() + ": barycentric coordinates must sum to 1");
  }
  return out;
}

bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Shortest text that reads back as exactly `v` (std::to_chars), then a separator.
char* appendNumber(char* out, double v, char separator) {
  out = std::to_chars(out, out + 32, v).ptr;
  *out++ = separator;
  return out;
}

// The samples as a .npy table of float64, one row per point, the text's columns, evaluated on
// every core a block of rows at a time, each block written as it is done.
void writeSamplesNpy(const std::string& path, const std::vector<SurfacePoint>& points, const Interpolant& interpolant,
                     const StandardErrorField* errors) {
  const size_t columns = errors ? 20 : 17;
  AtomicFileWriter file(path);
  const std::string header = npyHeader(points.size(), columns);
  file.write(header.data(), header.size());
  constexpr size_t kBlock = 65536;
  std::vector<double> rows(std::min(kBlock, points.size()) * columns);
  for (size_t first = 0; first < points.size(); first += kBlock) {
    const size_t count = std::min(kBlock, points.size() - first);
    parallelFor(count, [&](size_t i) {
      const SurfacePoint& point = points[first + i];
      const Sample s = interpolant.evaluate(point.element, point.x);
      double* row = &rows[i * columns];
      for (double v : {double(point.element), point.x.x, point.x.y, point.x.z, point.distance, s.B.r, s.B.g, s.B.b})
        *row++ = v;
      for (const Vec3& g : s.gradient)
        for (int c = 0; c < 3; ++c) *row++ = g[c];
      if (errors) {
        const Rgb error = errors->at(point);
        for (int c = 0; c < 3; ++c) *row++ = error[c];
      }
    });
    file.write(reinterpret_cast<const char*>(rows.data()), count * columns * sizeof(double));
  }
  file.commit();
}

}  // namespace

int runSample(const SampleOptions& options) {
  const Method method = methodFromName(options.method);
  InterpolantOptions interpolantOptions = interpolantOptionsFromNames(options.diagonal, options.variant,
                                                                      options.smoothing, options.estimateGradients);
  const ViewedFile viewed = openForViewing(options.file, options.elementSize, options.import, options.light, nullptr,
                                           solveProgressOnTerminal(options.light));
  if (!viewed.lighting.empty())
    std::fprintf(stderr, "radview: %s: scene lighting: %s\n", options.file.c_str(), viewed.lighting.c_str());
  const RadiosityMesh& mesh = viewed.mesh;
  if (methodInfo(method).viewDependent) {
    int width = 0, height = 0;
    parseSize(options.size, width, height);
    const Camera camera = cameraFromSpec(options.camera, mesh.bounds(), viewed.file.scene.cameras);
    interpolantOptions.view = ScreenView{camera.clipFromWorld(double(width) / height), Vec2(width, height)};
  }
  if (!options.out.empty() && !endsWith(options.out, ".npy"))
    throw Error("--out '" + options.out + "': expected a .npy file");
  std::string text, source = "--points";
  std::vector<PointRequest> requests;
  if (endsWith(options.points, ".npy")) {
    source = options.points;
    requests = pointsFromNpy(options.points, mesh.elements.size());
  } else if (options.points == "-") {
    text = readAll(std::cin);
    source = "standard input";
  } else if (std::ifstream in(options.points);
             in && options.points.find(' ') == std::string::npos && options.points.find(';') == std::string::npos) {
    text = readAll(in);
    source = options.points;
  } else {
    text = options.points;
  }
  if (requests.empty()) requests = parsePoints(text, source, mesh.elements.size());
  const double maxDistance = options.maxDistance >= 0.0 ? options.maxDistance : 1e-3 * mesh.bounds().diagonal();

  // Every point is placed before anything is printed, so a bad one leaves no partial output;
  // the first bad one in the input is the one reported.
  const std::vector<SurfacePoint> points =
      placePoints(mesh, requests.size(), [&](size_t i) { return requests[i].query; }, maxDistance);
  if (const size_t i = firstOffSurface(points, maxDistance); i < points.size())
    throw Error("point " + (requests[i].entry.empty() ? source + " row " + std::to_string(requests[i].row)
                                                       : "'" + std::string(requests[i].entry) + "'") +
                " is off every surface: the nearest element (" + std::to_string(points[i].element) + ") is " +
                std::to_string(points[i].distance) + " away, more than --max-distance " + std::to_string(maxDistance));
  const std::unique_ptr<Interpolant> interpolant = makeInterpolant(mesh, method, interpolantOptions);
  std::optional<StandardErrorField> errors;
  if (options.standardError) {
    if (!mesh.hasStandardErrors)
      throw Error(options.file, "has no standard errors for --standard-error (its solver did not estimate them)");
    errors.emplace(mesh, interpolantOptions);
  }
  const StandardErrorField* errorField = errors ? &*errors : nullptr;
  if (!options.out.empty()) {
    writeSamplesNpy(options.out, points, *interpolant, errorField);
    return 0;
  }
  std::printf(
      "# radview sample %s --method %s: element x y z distance B_r B_g B_b "
      "dBr/dx dBr/dy dBr/dz dBg/dx dBg/dy dBg/dz dBb/dx dBb/dy dBb/dz%s\n",
      options.file.c_str(), methodName(method).c_str(), options.standardError ? " SE_r SE_g SE_b" : "");
  // Evaluated and formatted on every core, a block of lines at a time, written in order.
  constexpr size_t kLine = 640, kBlock = 16384;  // a line is at most 10 + 21 * 25 characters
  std::vector<char> lines(kLine * std::min(kBlock, points.size()));
  std::vector<size_t> lengths(std::min(kBlock, points.size()));
  for (size_t first = 0; first < points.size(); first += kBlock) {
    const size_t count = std::min(kBlock, points.size() - first);
    parallelFor(count, [&](size_t i) {
      const SurfacePoint& point = points[first + i];
      const Sample s = interpolant->evaluate(point.element, point.x);
      char* const begin = &lines[i * kLine];
      char* out = std::to_chars(begin, begin + 16, point.element).ptr;
      *out++ = ' ';
      for (double v : {point.x.x, point.x.y, point.x.z, point.distance, s.B.r, s.B.g, s.B.b})
        out = appendNumber(out, v, ' ');
      for (const Vec3& g : s.gradient)
        for (int k = 0; k < 3; ++k) out = appendNumber(out, g[k], ' ');
      if (errorField) {
        const Rgb error = errorField->at(point);
        for (int k = 0; k < 3; ++k) out = appendNumber(out, error[k], ' ');
      }
      out[-1] = '\n';
      lengths[i] = size_t(out - begin);
    });
    for (size_t i = 0; i < count; ++i) std::fwrite(&lines[i * kLine], 1, lengths[i], stdout);
  }
  return 0;
}

}  // namespace radview
