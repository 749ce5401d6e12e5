#pragma once
// The command-line options that say how another tool's mesh is read (import/import_options.h),
// shared by the viewer and every subcommand that opens a file.
#include "import/import_options.h"

#include <CLI/CLI.hpp>

namespace radview {

void addImportOptions(CLI::App& command, ImportOptions& import);

}  // namespace radview
