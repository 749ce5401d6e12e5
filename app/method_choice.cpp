#include "app/method_choice.h"

#include "core/strings.h"
#include "interp/method_registry.h"

#include <algorithm>
#include <cstdio>

namespace radview {

CLI::Validator methodChoice(const std::vector<std::string>& names) {
  return CLI::Validator(
      [names](std::string& value) -> std::string {
        for (const MethodInfo& info : methodRegistry())
          if (!info.alias.empty() && info.alias == value) {
            // Kept for older scripts; one name per thing is what the help and messages use.
            std::fprintf(stderr, "radview: note: '%s' is the older name of '%s', which radview uses\n",
                         info.alias.c_str(), info.name.c_str());
            value = info.name;
          }
        if (std::find(names.begin(), names.end(), value) != names.end()) return {};
        return value + " not in {" + joined(names, ",") + "}";
      },
      "{" + joined(names, ",") + "}");
}

std::string methodHelp(bool viewIndependentOnly) {
  std::string help = "Interpolant (C&W §9.2):";
  for (const MethodInfo& info : methodRegistry())
    if (!viewIndependentOnly || !info.viewDependent) help += "\n  " + info.name + ": " + info.summary;
  return help;
}

void addGatherMethodOption(CLI::App& command, std::string& method, const std::string& help) {
  command.add_option("--gather-method", method, help)->check(methodChoice(methodNames(true)))->capture_default_str();
  command.add_option("--gather-interpolant", method)
      ->check(methodChoice(methodNames(true)))
      ->each([](const std::string&) {  // kept for older scripts
        std::fprintf(stderr,
                     "radview: note: --gather-interpolant is the older name of --gather-method, which "
                     "radview uses\n");
      })
      ->group("");
}

}  // namespace radview
