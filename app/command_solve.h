#pragma once
// radview solve: a scene in, a radiosity solution file out (progressive refinement with
// adaptive subdivision, renderer/solve/radiosity_solve.h).
#include "discontinuity/discontinuity_mesher.h"
#include "solve/radiosity_solve.h"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace radview {

struct SolveOptions {
  std::string file;
  std::string out;
  bool triangulateTVertices = false;
  bool noAmbient = false;
  std::vector<std::string> views;     // --view: camera specs; "file" stands for each of the scene's cameras
  std::string viewSize = "1024x768";  // --view-size
  SolveSettings settings;             // the options bind to its fields: the library's defaults are the command's
};

CLI::App* addSolveCommand(CLI::App& app, SolveOptions& options);
int runSolve(const SolveOptions& options);

}  // namespace radview
