#include "gl/display_views.h"

#include "core/error.h"
#include "core/strings.h"

namespace radview::gl {

const std::vector<DisplayViewInfo>& displayViewRegistry() {
  static const std::vector<DisplayViewInfo> registry = {
      {DisplayView::Normal, "normal", "Normal", "the radiosity, exposed and sRGB-encoded", true},
      {DisplayView::Value, "value", "Value, false colour",
       "the displayed luminance on a colour scale, with a colour bar", true},
      {DisplayView::GradientMagnitude, "gradient", "Gradient magnitude",
       "the displayed luminance's gradient per pixel: Mach bands are jumps in it", true},
      {DisplayView::Isolines, "isolines", "Isolines", "the normal display with lines between luminance levels", true},
      {DisplayView::Difference, "difference", "Difference",
       "displayed luminance minus another method's or a reference image's, in 8-bit steps", false},
      {DisplayView::StandardError, "standard-error", "Standard error",
       "the solver's standard error of each nodal B, interpolated linearly, in displayed 8-bit steps", true},
  };
  return registry;
}

const DisplayViewInfo& displayViewInfo(DisplayView view) { return displayViewRegistry().at(size_t(view)); }

std::vector<std::string> displayViewNames() {
  std::vector<std::string> names;
  for (const DisplayViewInfo& info : displayViewRegistry()) names.push_back(info.name);
  return names;
}

DisplayView displayViewFromName(const std::string& name) {
  for (const DisplayViewInfo& info : displayViewRegistry())
    if (info.name == name) return info.view;
  throw Error("unknown display view '" + name + "' (expected one of " + joined(displayViewNames()) + ")");
}

DisplayView nextCycledView(DisplayView view, bool hasStandardErrors) {
  const std::vector<DisplayViewInfo>& views = displayViewRegistry();
  for (size_t step = 1; step <= views.size(); ++step) {
    const DisplayViewInfo& next = views[(size_t(view) + step) % views.size()];
    if (next.cycled && (hasStandardErrors || next.view != DisplayView::StandardError)) return next.view;
  }
  return view;
}

}  // namespace radview::gl
