// The C1 methods' pieces set up on another thread (MeshRenderer::piecesSetup, as the viewer does
// beside its frame loop), then adopted: the same image as pieces built by render() itself.
#include "core/camera.h"
#include "gl/egl_context.h"
#include "gl/mesh_renderer.h"
#include "gl/method_pieces.h"
#include "import/load_file.h"
#include "tests/gl/oblique_view.h"

#include <gtest/gtest.h>

#include <thread>

namespace radview::gl {
namespace {

RadiosityMesh discontinuities() {
  return loadFile(std::string(RADVIEW_SOURCE_DIR) + "/assets/discontinuities.gltf").mesh;
}

void expectSetUpOnAnotherThreadDrawsTheSame(Method method) {
  EglContext context;
  RenderSettings settings;
  settings.method = method;
  settings.splitLines = true;
  MeshRenderer built;
  built.setMesh(discontinuities());
  EXPECT_TRUE(built.piecesSetup(settings));  // not built yet
  built.render(test::obliqueView(), settings, 96, 96);
  EXPECT_FALSE(built.piecesSetup(settings));  // render() built them

  MeshRenderer adopted;
  adopted.setMesh(discontinuities());
  const std::function<DeferredSetup()> job = adopted.piecesSetup(settings);
  ASSERT_TRUE(job);
  DeferredSetup setup;
  std::thread worker([&] { setup = job(); });
  worker.join();
  adopted.adoptPieces(setup, settings.splitLines);
  EXPECT_FALSE(adopted.piecesSetup(settings));
  adopted.render(test::obliqueView(), settings, 96, 96);

  const LinearImage a = built.readLinear(), b = adopted.readLinear();
  ASSERT_EQ(a.rgba.size(), b.rgba.size());
  size_t covered = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) {
    ASSERT_EQ(a.rgba[i], b.rgba[i]) << "channel " << i;
    covered += i % 4 == 3 && a.rgba[i] > 0.0f;
  }
  EXPECT_GT(covered, 2000u);
}

TEST(BackgroundPieces, CloughTocherSetUpOnAnotherThreadDrawsTheSame) {
  expectSetUpOnAnotherThreadDrawsTheSame(Method::CloughTocher);
}

TEST(BackgroundPieces, PowellSabinSetUpOnAnotherThreadDrawsTheSame) {
  expectSetUpOnAnotherThreadDrawsTheSame(Method::C1Quadratic);
}

// Only what render() would build now is offered: nothing for the methods without pieces, the
// tessellated ones or a shown image; and a set-up made for a mesh no longer drawn is dropped.
TEST(BackgroundPieces, OnlyWhatRenderWouldBuildIsOfferedAndStaleSetUpsAreDropped) {
  EglContext context;
  MeshRenderer renderer;
  renderer.setMesh(discontinuities());
  RenderSettings settings;
  for (Method m : {Method::Flat, Method::Gouraud, Method::Bilinear, Method::Quadratic}) {
    settings.method = m;
    EXPECT_FALSE(renderer.piecesSetup(settings)) << int(m);
  }
  settings.method = Method::CloughTocher;
  settings.tessellation = 4;
  EXPECT_FALSE(renderer.piecesSetup(settings));
  settings.tessellation = 0;
  settings.surfaceHeight = 0.1;
  EXPECT_FALSE(renderer.piecesSetup(settings));
  settings.view = DisplayView::Difference;  // which draws the flat surface
  EXPECT_TRUE(renderer.piecesSetup(settings));
  settings = RenderSettings();
  settings.method = Method::CloughTocher;

  const DeferredSetup stale = renderer.piecesSetup(settings)();
  renderer.setMesh(discontinuities());
  renderer.adoptPieces(stale, false);
  EXPECT_TRUE(renderer.piecesSetup(settings));
  renderer.adoptPieces(renderer.piecesSetup(settings)(), false);
  EXPECT_FALSE(renderer.piecesSetup(settings));
  settings.cloughTocher = CloughTocherVariant::Book;  // other pieces
  EXPECT_TRUE(renderer.piecesSetup(settings));
}

}  // namespace
}  // namespace radview::gl
