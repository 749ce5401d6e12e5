#pragma once
// The command-line options of what is drawn and how (render, the viewer, the Python module's
// render): the display's, and the ray tracers' (final gather, path tracer).
#include "app/commands.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace radview {

// The help text of a FILE argument, and of --smoothing.
extern const char* const kFileHelp;
extern const char* const kSmoothingHelp;

// --method (one of `methods`), --camera, --exposure, --view and every other display option.
void addDisplayOptions(CLI::App& command, DisplayOptions& display, const std::vector<std::string>& methods);
// --spp (its help says what `spp` counts), --seed, --gather-method, --emitter-samples.
void addGatherOptions(CLI::App& command, GatherOptions& gather, const std::string& spp);

}  // namespace radview
