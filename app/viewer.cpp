#include "app/background_open.h"
#include "app/background_pieces.h"
#include "app/commands.h"
#include "app/examples.h"
#include "app/frame_log.h"
#include "app/solve_progress_bar.h"
#include "app/viewer_gather.h"
#include "app/viewer_input.h"
#include "app/viewer_panel.h"
#include "core/error.h"
#include "core/image_difference.h"
#include "core/memory_budget.h"
#include "edit/edge_picker.h"
#include "gather/traced_surfaces.h"
#include "interp/method_registry.h"
#include "mesh/solution_file.h"
#include "mesh/topology.h"
#include "scene/camera_presets.h"
#include "solve/background_solve.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>

namespace radview {

namespace {

std::string glfwFailure;

void adoptViewedFile(ViewerState& state, ViewedFile viewed) {
  state.viewed = std::move(viewed);
  const std::string& path = state.viewed.file.path;
  state.homeCamera = cameraFromSpec("", state.viewed.mesh.bounds(), state.viewed.file.scene.cameras);
  state.camera = state.homeCamera;
  state.rollSteps = 0;
  state.pathToOpen = path;
  state.solutionPath =
      std::filesystem::path(path).stem().string() + (state.viewed.file.isSolution ? "-edited.glb" : "-solved.glb");
  state.solveStatus.clear();
  state.solving = false;
  state.status = "opened " + path;
  for (const std::string& w : state.viewed.file.warnings) state.status += "\nwarning: " + w;
  // Opened from the list of examples: shown the way the example asks for.
  if (const Example* example = state.requestedExample; example && exampleForFile(path) == example) {
    gl::RenderSettings& s = state.settings;
    s.method = example->method;
    s.elementEdges = example->elementEdges;
    s.discontinuityEdges = example->discontinuityEdges;
    s.tVertices = example->tVertices;
    state.gather.on = false;
  }
  state.requestedExample = nullptr;
}

std::string nextScreenshotName() {
  for (int i = 1;; ++i) {
    const std::string name = "radview-screenshot-" + std::to_string(i) + ".png";
    if (!std::filesystem::exists(name)) return name;
  }
}

// Where no display exists, the viewer's job becomes a headless render of the same file.
int renderInstead(const ViewerOptions& options, ViewedFile viewed) {
  const std::string out =
      std::filesystem::absolute("radview-" + std::filesystem::path(viewed.file.path).stem().string() + ".png");
  std::fprintf(stderr, "radview: no display (%s); rendering headless instead\n", glfwFailure.c_str());
  int width = 0, height = 0;
  parseSize(options.size, width, height);
  // The window would have solved a scene in the background; the render solves it first.
  const std::optional<RayTracer> tracer = rayTracerFromName(options.display.method);
  const bool needsSolution = !tracer || rayTracerInfo(*tracer).needsSolution;
  const bool solve = !viewed.file.isSolution && !options.light.directOnly && needsSolution;
  const auto shown = std::make_shared<const ViewedFile>(
      solve ? openForViewing(options.file, options.display.elementSize, options.import, options.light, nullptr,
                             solveProgressOnTerminal(options.light))
            : std::move(viewed));
  if (tracer)
    renderRayTraced(*shown, options.display, options.gather, width, height, out, "");
  else
    renderHeadless(shown, options.display, width, height, out);
  if (!shown->lighting.empty() && needsSolution) std::printf("scene lighting: %s\n", shown->lighting.c_str());
  return 0;
}

// Ends GLFW, and ImGui when it was started, however runViewer is left.
struct WindowSession {
  GLFWwindow* window = nullptr;
  bool imgui = false;
  ~WindowSession() {
    if (imgui) {
      ImGui_ImplOpenGL3_Shutdown();
      ImGui_ImplGlfw_Shutdown();
      ImGui::DestroyContext();
    }
    if (window) glfwDestroyWindow(window);
    glfwTerminate();
  }
};

// What the viewer's loop owns besides the window: the renderer, and the work it runs beside
// the frames (opening files, solving, setting up C1 pieces, the final gather). Each handle*
// does what the panel or a key asked for in this frame; a failure goes to the status line.
struct ViewerWork {
  gl::MeshRenderer renderer;
  BackgroundSolve solve;
  BackgroundOpen opener;
  BackgroundPieces pieces;
  ViewerGather gather;
  uint64_t meshVersion = 0;  // counts the meshes given to the renderer, for the gather
  std::optional<uint64_t> boundsVersion;  // the mesh version `bounds` is of
  Bounds bounds;
  SceneLightOptions light;   // a scene opened is solved with these settings, unless directOnly
  ContinuityEditor editor;
  std::unique_ptr<EdgePicker> picker;  // over the shown mesh's elements; made at the first pick

  // A new mesh on screen (a file opened, a solve's progress): edits and picks were of the old.
  void meshReplaced(ViewerState& state) {
    editor.clear();
    picker.reset();
    state.undoSteps = 0;
    state.pickedEdge.reset();
    state.pickedDescription.clear();
    if (state.settings.view == gl::DisplayView::StandardError && !state.viewed.mesh.hasStandardErrors)
      state.settings.view = gl::DisplayView::Normal;
  }

  // The edited mesh to the renderer; the pieces and the gather see a new version.
  void showEdited(ViewerState& state) {
    renderer.setEditedMesh(state.viewed.mesh, editor.topology(state.viewed.mesh));
    ++meshVersion;
    state.undoSteps = editor.steps();
    if (state.pickedEdge) state.pickedDescription = describePicked(state.viewed.mesh, *state.pickedEdge);
  }

  std::string describePicked(const RadiosityMesh& mesh, EdgeRef ref) {
    const EdgeDescription d = describeEdge(mesh, *editor.topology(mesh), ref);
    std::ostringstream text;
    text.precision(4);
    text << "edge " << ref.edge << " of element " << ref.element << ": " << toString(d.continuity) << ", "
         << (d.sides.size() == 2   ? (d.ownNodes ? "each side its own nodes" : "sides share their nodes")
             : d.sides.size() == 1 ? "on the boundary"
                                   : "non-manifold");
    for (uint32_t n : {d.a, d.b}) {
      const Node& node = mesh.nodes[n];
      text << "\nnode " << n << " at (" << node.position.x << ", " << node.position.y << ", " << node.position.z
           << "), B (" << node.B.r << ", " << node.B.g << ", " << node.B.b << ")";
    }
    return text.str();
  }

  // A finished click or drag in edit mode retags the edges it passed; undo steps back. The
  // stroke is in window coordinates; the view is `view` framebuffer pixels from `left` on, the
  // framebuffer `scale` times the window.
  void handleEdit(ViewerState& state, int left, int width, int height, double scale) {
    if (state.undoRequested) {
      state.undoRequested = false;
      try {
        if (editor.undo(state.viewed.mesh)) {
          showEdited(state);
          state.status = "undone: " + std::to_string(editor.steps()) + " continuity edits left";
        }
      } catch (const std::exception& e) {
        state.status = e.what();
      }
    }
    if (state.stroke.empty()) return;
    std::vector<std::pair<double, double>> stroke = std::move(state.stroke);
    state.stroke.clear();
    if (width <= 0 || height <= 0) return;
    try {
      if (!picker) picker = std::make_unique<EdgePicker>(state.viewed.mesh);
      for (auto& [x, y] : stroke) x = x * scale - left, y *= scale;
      const Camera framed = framedFor(state.camera, double(width) / height);
      const std::vector<EdgeRef> edges = picker->pickAlong(framed, width, height, stroke);
      if (edges.empty()) {
        state.status = "no element edge there (click within a few pixels of one)";
        return;
      }
      editor.startFrom(renderer.givenMeshTopology());  // the renderer's is the shown mesh's
      const std::optional<std::string> refused = editor.cycle(state.viewed.mesh, edges);
      state.pickedEdge = edges.back();
      showEdited(state);
      state.status =
          refused ? *refused : std::to_string(edges.size()) + (edges.size() == 1 ? " edge" : " edges") + " retagged";
    } catch (const std::exception& e) {
      state.status = e.what();
    }
  }

  // A dropped file or the panel's Open, loaded and prepared in the background. All or
  // nothing: the previous file stays on screen and in the panel unless the new one both loads
  // and uploads.
  void handleOpen(ViewerState& state, ViewerInput& input, double elementSize, const ImportOptions& import) {
    if (!input.droppedPath.empty() || state.openRequested) {
      const std::string path = input.droppedPath.empty() ? state.pathToOpen : input.droppedPath;
      input.droppedPath.clear();
      state.openRequested = false;
      opener.start(path, elementSize, import);
    }
    if (opener.running()) state.status = opener.status();
    if (std::optional<BackgroundOpen::Result> opened = opener.take()) {
      try {
        if (!opened->viewed) throw Error(opened->error);
        solve.abandon();  // its partial solutions belong to the old scene
        renderer.adoptMesh(std::move(*opened->prepared));
        ++meshVersion;
        adoptViewedFile(state, std::move(*opened->viewed));
        meshReplaced(state);
        state.solveRequested = !light.directOnly && !state.viewed.file.isSolution;
      } catch (const std::exception& e) {
        state.status = e.what();
      }
    }
  }

  // Starting or cancelling the background solve, and showing what it has published.
  // A solve for the view meshes for the scene's columns as they are when it starts.
  void handleSolve(ViewerState& state, int width, int height) {
    if (state.solveRequested) {
      state.solveRequested = false;
      SolveSettings settings = light.solve;
      if (state.solveForView && width > 0 && height > 0)
        settings.subdivision.views = {{framedFor(state.camera, double(width) / height), width, height, "the window's"}};
      solve.start(state.viewed.file.scene, settings);
    }
    if (state.cancelSolveRequested) {
      state.cancelSolveRequested = false;
      solve.cancel();
    }
    if (std::optional<RadiosityMesh> solved = solve.takeSolution()) {
      try {
        renderer.setMesh(*solved);
        ++meshVersion;
        state.viewed.mesh = std::move(*solved);
        state.viewed.directLightOnly = false;
        meshReplaced(state);
      } catch (const std::exception& e) {
        state.status = e.what();
      }
    }
    // The status while solving, and once more in the frame it stops.
    const bool solving = solve.running();
    if (solving || state.solving) state.solveStatus = solve.status();
    state.solving = solving;
  }

  void handleReference(ViewerState& state) {
    if (!state.referenceRequested) return;
    state.referenceRequested = false;
    try {
      renderer.setReferenceImage(readReferenceImage(state.referencePath));
      state.status = "reference image " + state.referencePath;
    } catch (const std::exception& e) {
      state.status = e.what();
    }
  }

  // The scene in the framebuffer's columns from `left` on (beside the panel): the gather's image
  // or the method (Gouraud while a C1 method's pieces are set up, when `piecesInBackground`),
  // and the difference's numbers.
  void drawScene(ViewerState& state, int left, int width, int height, int frame, bool waitForSpp,
                 bool piecesInBackground) {
    try {
      // The bounds once per mesh, not per frame: a sweep over every node (100 MB at 10^6 elements).
      if (boundsVersion != meshVersion) {
        bounds = state.viewed.mesh.bounds();
        boundsVersion = meshVersion;
      }
      fitClipPlanes(state.camera, bounds);
      const Camera framed = framedFor(state.camera, double(width) / height);
      // The final gather waits for a scene's solve to publish a solution: over direct light alone
      // it would show light the scene does not have.
      const bool awaitingSolution = state.gather.on && !state.gather.pathTrace && state.viewed.directLightOnly &&
                                    (state.solving || state.solveRequested);
      if (state.gather.on && !awaitingSolution &&
          (!state.viewed.file.gatherRefusal.empty() || (!state.gather.pathTrace && state.viewed.directLightOnly))) {
        state.gather.on = false;
        checkRayTracingRuns(state.viewed, state.gather.pathTrace ? "the path tracer" : "the final gather");
      }
      GatherControls shown = state.gather;
      if (awaitingSolution) shown.on = false;
      gather.update(shown, state.viewed.mesh, state.viewed.file.scene, meshVersion, framed, width, height, renderer,
                    waitForSpp);
      if (!awaitingSolution) state.gather.progress = shown.progress;
      const gl::RenderSettings drawn =
          piecesInBackground ? pieces.frame(renderer, state.settings, meshVersion, state.status) : state.settings;
      state.drawnMethod = drawn.method;
      renderer.render(framed, drawn, width, height);
      renderer.presentToDefaultFramebuffer(left, width, height);
    } catch (const std::exception& e) {
      state.status = e.what();
    }
    state.gpuFrameMs = renderer.gpuFrameMs();
    state.tessellation = renderer.tessellationStatistics();
    state.triangles = renderer.triangleCount();
    // The difference's numbers, twice a second or so: reading both images back costs a few ms.
    if (state.settings.view == gl::DisplayView::Difference && frame % 30 == 1) {
      try {
        std::ostringstream text;
        text << displayDifference(renderer.readLinear(), renderer.readComparison(), std::exp2(state.settings.exposure));
        state.difference = text.str();
      } catch (const std::exception& e) {
        state.difference = e.what();
      }
    }
  }
};

void handleWriteSolution(ViewerState& state) {
  if (!state.writeSolutionRequested) return;
  state.writeSolutionRequested = false;
  try {
    writeSolution(state.viewed.mesh, state.solutionPath, state.viewed.file.scene.cameras);
    state.status = "solution written to " + state.solutionPath;
  } catch (const std::exception& e) {
    state.status = e.what();
  }
}

// The window (panel included) to `path`; false, with the reason in the status line, when it
// cannot be written.
bool writeScreenshot(ViewerState& state, const std::string& path, int width, int height) {
  try {
    writePng(gl::readDefaultFramebuffer(width, height), path);
    state.status = "screenshot written to " + path;
    return true;
  } catch (const std::exception& e) {
    state.status = e.what();
    return false;
  }
}

// Dear ImGui on the window, at the monitor's content scale (1 on a plain X server, 2 on a
// typical HiDPI one); the scene is rendered at the framebuffer's own resolution.
void startImGui(GLFWwindow* window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui::StyleColorsDark();
  float xScale = 1.0f, yScale = 1.0f;
  glfwGetWindowContentScale(window, &xScale, &yScale);
  if (xScale > 1.0f) {
    ImGui::GetStyle().ScaleAllSizes(xScale);
    ImGui::GetIO().FontGlobalScale = xScale;
  }
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 450 core");
}

// The panel's width before its first frame, so that the first frame is framed beside it.
float initialPanelWidth() { return kPanelWidth * ImGui::GetIO().FontGlobalScale; }

}  // namespace

int runViewer(const ViewerOptions& options) {
  int width = 0, height = 0;
  parseSize(options.size, width, height);
  // The viewer can run the final gather at the window's size (key 9).
  checkImageMemory(options.size, width, height, kGatherBytesPerPixel, "the window's final gather");
  if (!options.screenshot.empty() && options.frames == 0)
    throw Error("--screenshot needs --frames N (the number of frames to run before taking it)");
  checkGatherOptions(options.gather);

  std::optional<FrameLog> frameLog;
  if (!options.frameLog.empty()) frameLog.emplace(options.frameLog);
  ViewedFile viewed = openForViewing(options.file, options.display.elementSize, options.import, kDirectLight);
  // A scene's final gather waits for the solve that starts with the window.
  const bool solveComing = !viewed.file.isSolution && !options.light.directOnly;
  const std::optional<RayTracer> tracer = rayTracerFromName(options.display.method);
  if (tracer && (!rayTracerInfo(*tracer).needsSolution || !solveComing))
    checkRayTracingRuns(viewed, "the " + rayTracerInfo(*tracer).noun);

  glfwSetErrorCallback([](int, const char* message) { glfwFailure = message; });
  if (!glfwInit()) {
    if (options.frames > 0) throw Error("cannot open a window: " + glfwFailure);
    return renderInstead(options, std::move(viewed));
  }
  WindowSession session;
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  session.window = glfwCreateWindow(width, height, "radview", nullptr, nullptr);
  if (!session.window) {
    // A display without OpenGL 4.5 (a remote X server, say): still show the file headless.
    if (options.frames > 0) throw Error("cannot open an OpenGL 4.5 core window: " + glfwFailure);
    return renderInstead(options, std::move(viewed));
  }
  GLFWwindow* window = session.window;
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);

  ViewerState state;
  // With --method final-gather or path-trace the GL method is the default one, drawn while the
  // view moves.
  DisplayOptions glDisplay = options.display;
  if (tracer) glDisplay.method = DisplayOptions().method;
  state.settings = settingsFrom(glDisplay);
  state.gather.on = tracer.has_value();
  state.gather.pathTrace = tracer == RayTracer::PathTrace;
  state.gather.interpolant = methodFromName(options.gather.interpolant);
  state.gather.emitterSamples = options.gather.emitterSamples;
  state.gather.seed = options.gather.seed;
  state.gather.targetSpp = options.gather.spp;
  ViewerWork work;
  work.renderer.setMesh(viewed.mesh);
  if (!options.display.reference.empty())
    work.renderer.setReferenceImage(readReferenceImage(options.display.reference));
  state.referencePath = options.display.reference;
  adoptViewedFile(state, std::move(viewed));
  if (!options.display.camera.empty())
    state.camera = state.homeCamera =
        cameraFromSpec(options.display.camera, state.viewed.mesh.bounds(), state.viewed.file.scene.cameras);
  // Interactive only: a run of --frames draws every frame with the method asked for.
  const bool piecesInBackground = options.frames == 0;
  // A scene is drawn with its direct light at once, and with the light it has as the solve
  // converges (the panel says which).
  work.light = options.light;
  state.solveRequested = !options.light.directOnly && !state.viewed.file.isSolution;

  ViewerInput input;
  input.state = &state;
  installInput(window, input);
  // A click shorter than a frame still reads as pressed at the next poll.
  glfwSetInputMode(window, GLFW_STICKY_MOUSE_BUTTONS, GLFW_TRUE);
  startImGui(window);
  session.imgui = true;
  state.panelWidth = initialPanelWidth();

  int status = 0;
  for (int frame = 1; !glfwWindowShouldClose(window); ++frame) {
    const auto start = std::chrono::steady_clock::now();
    const bool lastFrame = options.frames > 0 && frame >= options.frames;
    glfwPollEvents();
    if (state.quitRequested) glfwSetWindowShouldClose(window, GLFW_TRUE);
    handleDrag(window, input);
    work.handleOpen(state, input, options.display.elementSize, options.import);
    int fbWidth = 0, fbHeight = 0, windowWidth = 0, windowHeight = 0;
    glfwGetFramebufferSize(window, &fbWidth, &fbHeight);
    glfwGetWindowSize(window, &windowWidth, &windowHeight);
    // The panel's columns in framebuffer pixels (a HiDPI framebuffer has more than the window).
    const int panel = windowWidth > 0 ? int(std::lround(state.panelWidth * double(fbWidth) / windowWidth)) : 0;
    work.handleSolve(state, fbWidth - panel, fbHeight);
    handleWriteSolution(state);
    work.handleReference(state);
    const float background[4] = {0.08f, 0.08f, 0.09f, 1.0f};
    glClearNamedFramebufferfv(0, GL_COLOR, 0, background);
    work.handleEdit(state, panel, fbWidth - panel, fbHeight, windowWidth > 0 ? double(fbWidth) / windowWidth : 1.0);
    if (fbWidth - panel > 0 && fbHeight > 0)
      work.drawScene(state, panel, fbWidth - panel, fbHeight, frame, lastFrame && options.framesWaitForSpp,
                     piecesInBackground);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    state.tVertexCount = work.renderer.tVertexCount();
    drawPanel(state);
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

    if (lastFrame && !options.screenshot.empty()) {
      if (writeScreenshot(state, options.screenshot, fbWidth, fbHeight)) {
        std::printf("%s\n", options.screenshot.c_str());
      } else {
        status = 1;
        std::fprintf(stderr, "radview: %s\n", state.status.c_str());
      }
    } else if (state.screenshotRequested) {
      writeScreenshot(state, nextScreenshotName(), fbWidth, fbHeight);
    }
    state.screenshotRequested = false;
    glfwSwapBuffers(window);
    state.cpuFrameMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (frameLog) frameLog->record(frame, state.cpuFrameMs, state.settings.method, state.drawnMethod, work.meshVersion);
    if (lastFrame) break;
  }
  return status;
}

}  // namespace radview
