#pragma once
// The command line's check of a method name: the registry's names (interp/method_registry.h)
// and their aliases, which it turns into the one name, so that every command reads the same.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace radview {

// Accepts `names` and the registry's aliases of them; refuses anything else with the
// "X not in {a,b,...}" message CLI11's IsMember gives.
CLI::Validator methodChoice(const std::vector<std::string>& names);

// "Interpolant (C&W §9.2):" and a line per method of the registry (those needing no view with
// `viewIndependentOnly`): its name and summary, for an option's help text.
std::string methodHelp(bool viewIndependentOnly = false);

// --gather-method: the method that reconstructs B^ under the final gather's integral (eq. 9.9),
// one that needs no view, into `method`; and --gather-interpolant, its older name, hidden, with a
// note. `help` is the option's help text.
void addGatherMethodOption(CLI::App& command, std::string& method, const std::string& help);

}  // namespace radview
