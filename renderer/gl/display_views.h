#pragma once
// What the display shows of the linear radiosity, in one table: each view's name on the command
// line (`--view`), its label in the viewer's panel, what it is for, and whether the viewer's C
// key cycles through it. The command line, the panel, the key and the help text read it.
#include <string>
#include <vector>

namespace radview::gl {

enum class DisplayView : int {
  Normal,             // exposure and sRGB
  Value,              // the displayed luminance on a colour scale, with a colour bar
  GradientMagnitude,  // of the displayed luminance per pixel: Mach bands are jumps in it
  Isolines,           // the normal display with lines between luminance levels
  Difference,         // displayed luminance minus a comparison's: another method, or an image
  StandardError,      // the solver's standard error of B, in displayed 8-bit steps
};

struct DisplayViewInfo {
  DisplayView view;
  std::string name;     // "gradient": the command line's
  std::string label;    // "Gradient magnitude": the panel's
  std::string summary;  // one line: what it shows
  bool cycled;          // the C key steps through it (not the difference, which needs a comparison)
};

// In enum order.
const std::vector<DisplayViewInfo>& displayViewRegistry();
const DisplayViewInfo& displayViewInfo(DisplayView view);
// "normal", "value", "gradient", "isolines", "difference", "standard-error"
std::vector<std::string> displayViewNames();
DisplayView displayViewFromName(const std::string& name);  // throws Error naming the known names
// The view after `view` among those the C key cycles through; the standard-error view only
// for a mesh that has them.
DisplayView nextCycledView(DisplayView view, bool hasStandardErrors);

}  // namespace radview::gl
