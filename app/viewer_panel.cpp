#include "app/viewer_panel.h"

#include "app/viewer_keys.h"

#include "app/commands.h"
#include "app/examples.h"
#include "interp/method_registry.h"
#include "mesh/display_mesh.h"
#include "mesh/standard_errors.h"

#include <imgui.h>

#include <string>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace radview {

void rotateView45(ViewerState& state) {
  roll(state.camera, glm::radians(45.0));
  state.rollSteps = (state.rollSteps + 1) % 8;
}

void setContinuityEditing(ViewerState& state, bool on) {
  state.editContinuity = on;
  if (on) state.settings.elementEdges = state.settings.discontinuityEdges = true;
}

void resetCamera(ViewerState& state) {
  state.camera = state.homeCamera;
  state.rollSteps = 0;
}

namespace {

// A combo of the registry's methods; `viewIndependentOnly` leaves out those that need a view.
void methodCombo(const char* title, Method& method, bool viewIndependentOnly) {
  if (!ImGui::BeginCombo(title, methodInfo(method).label.c_str())) return;
  for (const MethodInfo& info : methodRegistry()) {
    if (viewIndependentOnly && info.viewDependent) continue;
    if (ImGui::Selectable(info.label.c_str(), info.method == method)) method = info.method;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s (%s)", info.summary.c_str(), info.section.c_str());
  }
  ImGui::EndCombo();
}

// ImGui 1.86 has no SeparatorText.
void section(const char* title) {
  ImGui::Spacing();
  ImGui::Separator();
  ImGui::TextDisabled("%s", title);
}

}  // namespace

// What the difference view subtracts, its scale, and what it measured.
void drawDifferenceControls(ViewerState& state) {
  gl::RenderSettings& s = state.settings;
  int against = static_cast<int>(s.comparison);
  ImGui::RadioButton("minus a method", &against, 0);
  ImGui::SameLine();
  ImGui::RadioButton("minus an image", &against, 1);
  s.comparison = static_cast<gl::RenderSettings::Comparison>(against);
  if (s.comparison == gl::RenderSettings::Comparison::Method) {
    methodCombo("Method, per pixel", s.comparisonMethod, false);
  } else {
    char buffer[1024];
    std::snprintf(buffer, sizeof buffer, "%s", state.referencePath.c_str());
    if (ImGui::InputText("##reference", buffer, sizeof buffer)) state.referencePath = buffer;
    ImGui::SameLine();
    if (ImGui::Button("Load")) state.referenceRequested = true;
    ImGui::TextDisabled(".exr from render --linear-out: linear; .png: display");
  }
  float steps = float(s.differenceScale * 255.0);
  if (ImGui::SliderFloat("Bar ends, 8-bit steps", &steps, 0.25f, 64.0f, "%.2f", ImGuiSliderFlags_Logarithmic))
    s.differenceScale = steps / 255.0;
  if (!state.difference.empty()) ImGui::TextWrapped("%s", state.difference.c_str());
}

// The thin-plate spline's lambda: by cross-validation per region, or one given (--smoothing).
void drawThinPlateControls(ThinPlateSettings& thinPlate) {
  bool automatic = !thinPlate.lambda;
  if (ImGui::Checkbox("Lambda by cross-validation", &automatic)) thinPlate.lambda = automatic ? std::nullopt
                                                                                              : std::optional(1e-3);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Per region between C-1 edges, the lambda generalised cross-validation prefers "
                      "(--smoothing auto); off: one lambda for every region");
  if (thinPlate.lambda) {
    float lambda = float(*thinPlate.lambda);
    ImGui::PushItemWidth(200);
    if (ImGui::SliderFloat("Lambda", &lambda, 1e-9f, 1e3f, "%.2e", ImGuiSliderFlags_Logarithmic))
      thinPlate.lambda = double(lambda);
    ImGui::PopItemWidth();
  }
}

// The standard-error view's scale, and what the solver estimated, in numbers.
void drawStandardErrorControls(ViewerState& state) {
  float steps = float(state.settings.differenceScale * 255.0);
  if (ImGui::SliderFloat("Bar top, 8-bit steps", &steps, 0.25f, 64.0f, "%.2f", ImGuiSliderFlags_Logarithmic))
    state.settings.differenceScale = steps / 255.0;
  if (!state.viewed.mesh.hasStandardErrors) return;
  const StandardErrorSummary errors = summariseStandardErrors(state.viewed.mesh);
  ImGui::TextWrapped("Luminance: median %.3g, 99th percentile %.3g, largest %.3g (mean B %.3g); %zu of %zu nodes above 0",
                     errors.median, errors.p99, errors.largest, errors.meanB, errors.uncertain, errors.nodes);
}

// The final gather (C&W §9.3.1) shown in place of the GL method: B^ under its integral, where
// it stops, and how far it has got.
void drawGatherControls(ViewerState& state) {
  GatherControls& g = state.gather;
  section(g.pathTrace ? "Path tracer (the true image)" : "Final gather (C&W 9.3.1, eq. 9.9)");
  ImGui::PushItemWidth(200);
  if (!g.pathTrace) {
    methodCombo("B^ method", g.interpolant, true);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Reconstructs the solution under the integral (the CPU interpolant, as radview sample)");
    ImGui::SliderInt("Shadow rays per pass", &g.emitterSamples, 1, 16);
  }
  ImGui::SliderInt("Stop at, spp", &g.targetSpp, 1, kMaxGatherSpp, "%d", ImGuiSliderFlags_Logarithmic);
  ImGui::PopItemWidth();
  ImGui::Checkbox("Pause", &g.paused);
  const GatherProgress& p = g.progress;
  const double raysPerSecond = p.seconds > 0.0 ? double(p.rays) / p.seconds : 0.0;
  if (!p.error.empty()) {
    ImGui::TextWrapped("%s", p.error.c_str());
  } else if (p.preview) {
    ImGui::Text("preview at 1/4 resolution, %.1f s, %.2fM rays/s", p.seconds, raysPerSecond * 1e-6);
  } else if (p.spp == 0) {
    ImGui::TextDisabled("starts when the view is still");
  } else {
    ImGui::Text("%d spp%s, %.1f s, %.2fM rays/s", p.spp,
                p.reachedTarget ? " (done)"
                : g.paused      ? " (paused)"
                                : "",
                p.seconds, raysPerSecond * 1e-6);
  }
  const char* method = methodInfo(state.settings.method).label.c_str();
  ImGui::TextDisabled("while the view moves: %s", method);
}

// A scene's solve in the background (radview solve's defaults), and writing what is shown.
void drawSolveControls(ViewerState& state) {
  section("Radiosity solution");
  if (state.viewed.file.isSolution) {
    ImGui::TextDisabled("as the file holds it%s", state.undoSteps > 0 ? ", with continuity edits" : "");
  } else if (state.solving) {
    if (ImGui::Button("Cancel solve [G]")) state.cancelSolveRequested = true;
  } else if (ImGui::Button("Solve [G]")) {
    state.solveRequested = true;
  }
  if (!state.viewed.file.isSolution) {
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "Progressive refinement with Embree visibility and adaptive subdivision, as radview solve; "
          "the partial solution is shown as it converges (with the ambient term)");
    if (!state.solving) {
      ImGui::SameLine();
      ImGui::Checkbox("for this view", &state.solveForView);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Subdivision splits only elements this view sees, those whose error shows on most pixels first "
            "(C&W 9.3), as radview solve --view");
    }
    ImGui::TextWrapped("%s",
                       state.solveStatus.empty() ? "showing direct light, unoccluded" : state.solveStatus.c_str());
  }
  char buffer[1024];
  std::snprintf(buffer, sizeof buffer, "%s", state.solutionPath.c_str());
  ImGui::PushItemWidth(240);
  if (ImGui::InputText("##solution", buffer, sizeof buffer)) state.solutionPath = buffer;
  ImGui::PopItemWidth();
  ImGui::SameLine();
  if (ImGui::Button("Write solution [Ctrl+S]")) state.writeSolutionRequested = true;
}

// Retagging edges in the view (Salesin, Lischinski, DeRose 1992), its undo, and the last edge.
void drawContinuityControls(ViewerState& state) {
  section("Continuity (Salesin et al. 1992)");
  bool on = state.editContinuity;
  if (ImGui::Checkbox("Edit: click or drag across edges [K]", &on)) setContinuityEditing(state, on);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Each edge clicked or crossed goes C1 -> C0 -> C-1 -> C1; C-1 splits shared nodes where it "
        "cuts the elements around them. Left drag draws the stroke instead of orbiting.");
  ImGui::SameLine();
  if (state.undoSteps == 0) ImGui::BeginDisabled();
  if (ImGui::Button("Undo [Ctrl+Z]")) state.undoRequested = true;
  if (state.undoSteps == 0) ImGui::EndDisabled();
  if (!state.pickedDescription.empty()) ImGui::TextWrapped("%s", state.pickedDescription.c_str());
}

// Labels beside the colour bar the false-colour views draw at the window's right edge.
void drawColourBarLabels(const ViewerState& state) {
  const gl::DisplayView view = state.settings.view;
  if (view != gl::DisplayView::Value && view != gl::DisplayView::Difference &&
      view != gl::DisplayView::StandardError)
    return;
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const double top = view == gl::DisplayView::Value ? 1.0 : state.settings.differenceScale * 255.0;
  const double bottom = view == gl::DisplayView::Difference ? -top : 0.0;
  for (int i = 0; i <= 4; ++i) {
    const double t = i / 4.0;
    char label[32];
    std::snprintf(label, sizeof label, view == gl::DisplayView::Difference ? "%+.3g" : "%.3g",
                  bottom + (top - bottom) * t);
    const float y = size.y * float(1.0 - t);
    const ImVec2 extent = ImGui::CalcTextSize(label);
    const float yText = std::clamp(y - extent.y * 0.5f, 0.0f, size.y - extent.y);
    draw->AddRectFilled(ImVec2(size.x - 20 - extent.x - 4, yText), ImVec2(size.x - 18, yText + extent.y),
                        IM_COL32(0, 0, 0, 160));
    draw->AddText(ImVec2(size.x - 20 - extent.x - 2, yText), IM_COL32(255, 255, 255, 255), label);
  }
  const char* unit = view == gl::DisplayView::Value ? "displayed luminance" : "8-bit steps";
  const ImVec2 extent = ImGui::CalcTextSize(unit);
  draw->AddText(ImVec2(size.x - 20 - extent.x - 2, size.y * 0.5f - extent.y * 2.0f), IM_COL32(255, 255, 255, 200),
                unit);
}

// The bundled files, each opened the way that shows what it demonstrates (app/examples.h).
void drawExamples(ViewerState& state) {
  if (!ImGui::CollapsingHeader("Examples", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const std::string shown = std::filesystem::path(state.viewed.file.path).filename().string();
  for (const Example& example : bundledExamples()) {
    if (ImGui::Selectable(example.title.c_str(), example.file == shown)) {
      try {
        state.pathToOpen = examplePath(example);
        state.openRequested = true;
        state.requestedExample = &example;
      } catch (const std::exception& e) {
        state.status = e.what();
      }
    }
    ImGui::Indent();
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("%s", example.demonstrates.c_str());
    ImGui::PopStyleColor();
    ImGui::Unindent();
  }
}

void drawPanel(ViewerState& state) {
  drawColourBarLabels(state);
  state.panelWidth = 0.0f;
  if (!state.panelShown) return;
  // Pinned to the left edge at full height, so the scene can be framed beside it.
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth * ImGui::GetIO().FontGlobalScale, display.y), ImGuiCond_Always);
  const bool open =
      ImGui::Begin("radview  (Tab hides this panel)", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
  if (!open) {  // collapsed to its title bar
    ImGui::End();
    return;
  }
  state.panelWidth = ImGui::GetWindowWidth();

  const ViewedFile& viewed = state.viewed;
  ImGui::TextWrapped("%s", std::filesystem::path(viewed.file.path).filename().c_str());
  const char* shown = viewed.file.isSolution      ? "solution"
                      : state.solveStatus.empty() ? "scene (direct light only: no shadows, no interreflection)"
                                                  : "scene (radiosity solve)";
  ImGui::Text("%s: %zu nodes, %zu elements", shown, viewed.mesh.nodes.size(), viewed.mesh.elements.size());
  if (!viewed.file.valueSource.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("B from %s", viewed.file.valueSource.c_str());
    ImGui::PopStyleColor();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("--colours linear|srgb reads the values the other way");
  }
  drawExamples(state);

  // One radio button per entry of the registry, two to a row: the interpolants, each with its
  // options below, then the ray tracers (numbered after the methods), which converge in the
  // background.
  const int methods = int(methodRegistry().size());
  const RayTracer shownTracer = state.gather.pathTrace ? RayTracer::PathTrace : RayTracer::FinalGather;
  int choice = state.gather.on ? methods + int(shownTracer) : int(state.settings.method);
  auto radio = [&](size_t column, const std::string& label, char key, int value, const std::string& summary,
                   const std::string& where) {
    if (column % 2) ImGui::SameLine(190);
    ImGui::RadioButton((label + " [" + key + "]").c_str(), &choice, value);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s (%s)", summary.c_str(), where.c_str());
  };
  section("Interpolant (C&W 9.2)");
  for (const MethodInfo& info : methodRegistry())
    radio(size_t(info.method), info.label, info.key, int(info.method), info.summary, info.section);
  if (choice < methods) {
    state.gather.on = state.gather.pathTrace = false;
    state.settings.method = static_cast<Method>(choice);
  }
  if (state.settings.method == Method::Gouraud) {
    ImGui::Checkbox("Perspective-correct [P]", &state.settings.perspectiveCorrect);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Off: interpolate linearly in screen space, as classic Gouraud hardware did (9.2, note 3)");
  }
  if (state.settings.method == Method::CloughTocher) {
    bool book = state.settings.cloughTocher == CloughTocherVariant::Book;
    if (ImGui::Checkbox("Book cross-boundary direction [V]", &book))
      state.settings.cloughTocher = book ? CloughTocherVariant::Book : CloughTocherVariant::AffineInvariant;
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Edge normal, as the text reads; off: centroid to centroid (affine invariant, default)");
  }
  if (state.settings.method == Method::ThinPlate) drawThinPlateControls(state.settings.thinPlate);
  if (state.settings.method == Method::ScanlineGouraud) ImGui::TextDisabled("depends on the view: press R (fig. 9.8)");
  if (state.settings.method == Method::Bilinear) ImGui::TextDisabled("exact per pixel");
  if (methodInfo(state.settings.method).bezierPieces()) {
    // Exact per pixel, a fixed tessellation level, or the adaptive level (C&W 9.2).
    int mode = state.settings.tessellation == 0 ? 0 : state.settings.tessellation == gl::kAdaptiveTessellation ? 2 : 1;
    ImGui::RadioButton("Per pixel", &mode, 0);
    ImGui::SameLine();
    ImGui::RadioButton("Fixed level", &mode, 1);
    ImGui::SameLine();
    ImGui::RadioButton("Adaptive", &mode, 2);
    if (mode == 0) state.settings.tessellation = 0;
    if (mode == 2) state.settings.tessellation = gl::kAdaptiveTessellation;
    if (mode == 1) {
      int level = state.settings.tessellation > 0 ? state.settings.tessellation : 4;
      ImGui::PushItemWidth(200);
      ImGui::SliderInt("Level", &level, 1, 64);
      ImGui::PopItemWidth();
      state.settings.tessellation = level;
    }
    if (mode == 2) {
      float steps = float(state.settings.tessellationTolerance * 255.0);
      ImGui::PushItemWidth(200);
      if (ImGui::SliderFloat("Tolerance, 8-bit steps", &steps, 0.05f, 8.0f, "%.2f", ImGuiSliderFlags_Logarithmic))
        state.settings.tessellationTolerance = steps / 255.0;
      ImGui::PopItemWidth();
    }
  }

  section("Ray traced, converging in the background");
  for (const RayTracerInfo& info : rayTracerRegistry())
    radio(size_t(info.tracer), info.label, info.key, methods + int(info.tracer), info.summary, info.section);
  if (choice >= methods) {
    state.gather.on = true;
    state.gather.pathTrace = RayTracer(choice - methods) == RayTracer::PathTrace;
  }
  if (state.gather.on) drawGatherControls(state);

  section("Display");
  float exposure = static_cast<float>(state.settings.exposure);
  ImGui::PushItemWidth(200);
  if (ImGui::SliderFloat("Exposure, stops", &exposure, -10.0f, 10.0f, "%.1f")) state.settings.exposure = exposure;
  ImGui::PopItemWidth();
  ImGui::PushItemWidth(200);
  if (ImGui::BeginCombo("View [C]", gl::displayViewInfo(state.settings.view).label.c_str())) {
    for (const gl::DisplayViewInfo& info : gl::displayViewRegistry()) {
      const bool lacking = info.view == gl::DisplayView::StandardError && !state.viewed.mesh.hasStandardErrors;
      const ImGuiSelectableFlags flags = lacking ? ImGuiSelectableFlags_Disabled : 0;
      if (ImGui::Selectable(info.label.c_str(), info.view == state.settings.view, flags))
        state.settings.view = info.view;
      if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s (--view %s)%s", info.summary.c_str(), info.name.c_str(),
                          lacking ? "; this mesh has none (radview's solver estimates them)" : "");
    }
    ImGui::EndCombo();
  }
  if (state.settings.view == gl::DisplayView::GradientMagnitude) {
    float scale = float(state.settings.gradientScale);
    if (ImGui::SliderFloat("Scale top, per pixel", &scale, 0.001f, 0.2f, "%.3f", ImGuiSliderFlags_Logarithmic))
      state.settings.gradientScale = scale;
  }
  if (state.settings.view == gl::DisplayView::Isolines) ImGui::SliderInt("Levels", &state.settings.isolineCount, 2, 64);
  if (state.settings.view == gl::DisplayView::Difference) drawDifferenceControls(state);
  if (state.settings.view == gl::DisplayView::StandardError) drawStandardErrorControls(state);
  ImGui::PopItemWidth();
  if (state.settings.view == gl::DisplayView::Value)
    ImGui::TextDisabled("colour bar (right edge): displayed luminance 0 .. 1");
  if (state.settings.view == gl::DisplayView::GradientMagnitude)
    ImGui::TextDisabled("Mach bands are jumps here; compare Gouraud with C1");
  ImGui::Checkbox("Element edges [E]", &state.settings.elementEdges);
  ImGui::Checkbox("Discontinuity edges [D]", &state.settings.discontinuityEdges);
  ImGui::SameLine();
  ImGui::TextColored(ImVec4(kDiscontinuityCm1Colour.r, kDiscontinuityCm1Colour.g, kDiscontinuityCm1Colour.b, 1), "C-1");
  ImGui::SameLine();
  ImGui::TextColored(ImVec4(kDiscontinuityC0Colour.r, kDiscontinuityC0Colour.g, kDiscontinuityC0Colour.b, 1), "C0");
  const std::string tLabel = "T-vertices (" + std::to_string(state.tVertexCount) + ") [T]";
  ImGui::Checkbox(tLabel.c_str(), &state.settings.tVertices);
  ImGui::Checkbox("Repair T-vertices (Baum et al.) [B]", &state.settings.repairTVertices);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Triangulate every element with a T-vertex before drawing (C&W 9.2)");
  if (methodInfo(state.settings.method).c1) ImGui::Checkbox("Split lines [L]", &state.settings.splitLines);
  if (methodInfo(state.settings.method).bezierPieces()) {
    bool surface = state.settings.surfaceHeight > 0.0;
    if (ImGui::Checkbox("Radiosity surface, fig. 9.13 [H]", &surface))
      state.settings.surfaceHeight = surface ? 0.15 : 0.0;
    if (surface) {
      float height = float(state.settings.surfaceHeight);
      ImGui::PushItemWidth(200);
      if (ImGui::SliderFloat("Height", &height, 0.01f, 1.0f, "%.2f")) state.settings.surfaceHeight = height;
      ImGui::PopItemWidth();
      ImGui::Checkbox("Control net [N]", &state.settings.controlNet);
    }
  }
  if (methodInfo(state.settings.method).bezierPieces() && state.settings.tessellation != 0)
    ImGui::Checkbox("Tessellation triangles [W]", &state.settings.tessellationTriangles);

  drawContinuityControls(state);
  drawSolveControls(state);

  section("View");
  if (ImGui::Button("Rotate 45 deg [R]")) rotateView45(state);
  ImGui::SameLine();
  ImGui::Text("%d x 45 deg", state.rollSteps);
  if (ImGui::Button("Reset camera [F]")) resetCamera(state);
  ImGui::SameLine();
  if (ImGui::Button("Screenshot [S]")) state.screenshotRequested = true;

  section("Open");
  char buffer[1024];
  std::snprintf(buffer, sizeof buffer, "%s", state.pathToOpen.c_str());
  if (ImGui::InputText("##path", buffer, sizeof buffer)) state.pathToOpen = buffer;
  ImGui::SameLine();
  if (ImGui::Button("Open")) state.openRequested = true;
  ImGui::TextDisabled("or drop a .gltf, .glb, .ply or .obj on the window");

  section("Frame");
  ImGui::Text("GPU %.2f ms   CPU %.2f ms", state.gpuFrameMs, state.cpuFrameMs);
  if (methodInfo(state.settings.method).bezierPieces()) {
    const gl::TessellationStatistics& t = state.tessellation;
    ImGui::Text("%zu patches, %zu draws, mean level %.2f", t.patches, t.draws, t.averageLevel);
    ImGui::Text("%zu triangles generated", t.trianglesGenerated);
  } else {
    ImGui::Text("%zu triangles", state.triangles);
  }
  if (!state.status.empty()) ImGui::TextWrapped("%s", state.status.c_str());
  if (ImGui::CollapsingHeader("Keys")) ImGui::TextUnformatted(shortcutHelp().c_str());
  ImGui::End();
}

}  // namespace radview
