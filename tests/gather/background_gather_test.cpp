// The viewer's background gather publishes what the final gather and the path tracer make run
// directly, pass for pass, and a cancelled gather publishes nothing more.
#include "gather/background_gather.h"

#include "gather/path_tracer.h"
#include "gather_scenes.h"

#include <gtest/gtest.h>

namespace radview {
namespace {

GatherSettings smallView() {
  GatherSettings settings;
  settings.width = 24;
  settings.height = 16;
  settings.camera = test::receiverCamera();
  return settings;
}

// Waits for the target and takes the last image published.
LinearImage imageAtTarget(BackgroundGather& gather, int spp) {
  gather.setTarget(spp, false);
  gather.waitForTarget();
  const GatherProgress progress = gather.progress();
  EXPECT_EQ(progress.error, "");
  EXPECT_FALSE(progress.preview);
  EXPECT_EQ(progress.spp, spp);
  EXPECT_TRUE(progress.reachedTarget);
  std::optional<LinearImage> image = gather.takeImage();
  EXPECT_TRUE(image.has_value()) << "nothing was published";
  return image ? *image : LinearImage{};
}

void expectSamePixels(const LinearImage& a, const LinearImage& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  ASSERT_EQ(a.rgba.size(), b.rgba.size());
  for (size_t i = 0; i < a.rgba.size(); ++i) ASSERT_EQ(a.rgba[i], b.rgba[i]) << "value " << i;
}

TEST(BackgroundGather, PublishesTheFinalGathersImageAtItsTarget) {
  const RadiosityMesh mesh = test::receiverUnderSquareEmitterMesh();
  BackgroundGather background;
  background.start(mesh, smallView());
  const LinearImage published = imageAtTarget(background, 3);
  FinalGather direct(mesh, smallView());
  direct.addPasses(3);
  expectSamePixels(published, direct.image());
  // More samples asked for later: it goes on from where it stopped.
  const LinearImage more = imageAtTarget(background, 5);
  direct.addPasses(2);
  expectSamePixels(more, direct.image());
}

TEST(BackgroundGather, PathTracesTheSceneItIsGiven) {
  const Scene scene = test::receiverUnderSquareEmitter();
  const RadiosityMesh mesh = test::receiverUnderSquareEmitterMesh();
  BackgroundGather background;
  background.start(mesh, smallView(), &scene);
  EXPECT_TRUE(background.pathTracing());
  const LinearImage published = imageAtTarget(background, 2);
  PathTraceSettings traced;
  traced.width = smallView().width;
  traced.height = smallView().height;
  traced.camera = smallView().camera;
  traced.seed = smallView().seed;
  PathTracer direct(scene, traced);
  direct.addPasses(2);
  expectSamePixels(published, direct.image());
}

TEST(BackgroundGather, ACancelledGatherPublishesNothingMore) {
  const RadiosityMesh mesh = test::receiverUnderSquareEmitterMesh();
  BackgroundGather background;
  background.start(mesh, smallView());
  background.setTarget(1000000, false);
  background.cancel();
  EXPECT_FALSE(background.settings().has_value());
  EXPECT_FALSE(background.takeImage().has_value());
  EXPECT_EQ(background.progress().spp, 0);
}

}  // namespace
}  // namespace radview
