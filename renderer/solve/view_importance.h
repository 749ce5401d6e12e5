#pragma once
// What the views of a solve see of its mesh, for meshing driven by the view (C&W §9.3: "if
// the mesh resolution is too coarse for a particular view, small features may be absent or
// incorrectly represented"; view information in the error metric that guides subdivision).
//
// An element's importance for a set of views is the number of their pixels that see its front
// side: its projected area with visibility, at the resolution it will be looked at. It is
// direct importance only, the eye's share of Smits, Arvo and Salesin's (1992) importance. The
// adjoint part, carried to surfaces that light what the eye sees, is left out on purpose:
// radview's subdivision refines receivers under fixed patches (Cohen et al. 1986) and values new
// nodes by replaying the shots already made, so splitting an element changes how it is displayed
// and nothing that any other surface receives. An element no view sees gains nothing from it.
#include "core/camera.h"
#include "mesh/radiosity_mesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace radview {

struct SolveView {
  Camera camera;
  int width = 640, height = 480;  // the pixels it is looked at with; the aspect is width / height
  std::string name;               // as the user gave it, for messages
};

// For each element, the pixels of all the views that see its front side through their centres
// (the GL renderer's samples: CameraRays), summed over the views. A pixel that sees an element
// from behind counts for none: the solution has no radiosity on that side.
std::vector<uint32_t> viewedPixels(const RadiosityMesh& mesh, const std::vector<SolveView>& views);

// The views that see some element from the front, and one line for each that does not: it sees
// nothing of the scene, or only the backs of surfaces (an eye inside a solid or behind a wall).
struct UsableViews {
  std::vector<SolveView> views;
  std::vector<std::string> warnings;
};
UsableViews usableViews(const RadiosityMesh& mesh, const std::vector<SolveView>& views);

}  // namespace radview
