#pragma once
// radview bench: the speed-versus-accuracy trade of every method and setting on one view of a
// file, against the per-pixel final gather (C&W §9.3.1) or the path tracer's true image as the
// reference.
#include "app/scene_light.h"
#include "bench/tradeoff.h"
#include "import/import_options.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace radview {

struct BenchOptions {
  std::string file;
  std::string camera;  // as render --camera
  std::string size = "512x512";
  double exposure = 0.0;
  std::string reference = "gather";  // the reference image: gather (eq. 9.9 over the solution) or path-trace
  int gatherRowSpp = 64;             // --reference path-trace: the final gather's row, samples per pixel
  int spp = 168;                     // the reference's samples per pixel, all runs together
  int runs = 4;             // independent runs of the reference (error_estimate.h): its noise from their spread
  std::string truth;        // a linear image to measure against instead of the gather (exact, no interval)
  double precision = 0.0;   // add passes until every row's interval half-width is below this (steps); 0: --spp
  double maxSeconds = 0.0;  // with --precision: stop adding passes after this long; 0: no limit
  int nodeSpp = 256;        // the reference at the nodes, for the error split (nodal_reference.h); 0: none
  std::string gatherMethod = "clough-tocher";  // B^ under the reference's integral
  int frames = 7;                              // timed frames per row (median)
  double rowSeconds = 3.0;                     // a row's timing stops after this, once 3 frames are in
  std::string levels = "1,2,4,8,16,32,64";     // tessellation levels of the quadratic and C1 methods
  std::string tolerances = "0.5,2";            // adaptive tessellation tolerances, 8-bit steps
  // Fixed levels whose triangles would outnumber the image's pixels this many times are not
  // measured (0: every level is).
  double maxTrianglesPerPixel = 16.0;
  std::string outDir = "bench";
  double elementSize = 0.0;  // scenes only
  ImportOptions import;      // other tools' meshes
  SceneLightOptions light;   // scenes: solved first, unless --direct-only
};

CLI::App* addBenchCommand(CLI::App& app, BenchOptions& options);
// Measures every row, writes the output folder and prints the table; returns the table's rows.
std::vector<TradeoffRow> measureTrade(const BenchOptions& options);
int runBench(const BenchOptions& options);

}  // namespace radview
