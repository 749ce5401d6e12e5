// The probe that decides whether the per-pixel methods move interpolated values to the pixel
// centre (gl/rasteriser_probe.h).
#include "gl/rasteriser_probe.h"
#include "gl/egl_context.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace radview::gl {
namespace {

TEST(RasteriserProbe, MeasuresInterpolationAndLeavesTheStateAsItWas) {
  EglContext context;
  GLuint framebuffer = 0;
  glCreateFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(3, 4, 50, 60);
  glEnable(GL_DEPTH_TEST);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glColorMaski(0, GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  glPixelStorei(GL_PACK_ROW_LENGTH, 7);
  glEnable(GL_CLIP_DISTANCE0);
  const double error = rasteriserInterpolationError();
  std::cout << context.description() << ": barycentric coordinates interpolated within " << error
            << " of the pixel centres'\n";
  // Snapped corners move them by about 1e-4; a probe that got its exact coordinates wrong
  // would be off by the coordinates themselves (0.1 or more).
  ASSERT_TRUE(std::isfinite(error));
  EXPECT_LT(error, 1e-2);
  // The decision follows the probe unless the environment overrides it.
  const char* choice = std::getenv("RADVIEW_PIXEL_CENTRE");
  EXPECT_EQ(pixelCentreCorrection(), choice ? std::string(choice) == "on" : !(error <= kSnappedInterpolationError));
  GLint bound = 0, viewport[4] = {};
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
  glGetIntegerv(GL_VIEWPORT, viewport);
  EXPECT_EQ(GLuint(bound), framebuffer);
  EXPECT_EQ(viewport[0], 3);
  EXPECT_EQ(viewport[3], 60);
  EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
  EXPECT_TRUE(glIsEnabled(GL_CLIP_DISTANCE0));
  GLint polygonMode[2] = {}, rowLength = 0;
  glGetIntegerv(GL_POLYGON_MODE, polygonMode);
  glGetIntegerv(GL_PACK_ROW_LENGTH, &rowLength);
  EXPECT_EQ(polygonMode[0], GL_LINE);
  EXPECT_EQ(rowLength, 7);
  GLboolean mask[4] = {};
  glGetBooleani_v(GL_COLOR_WRITEMASK, 0, mask);
  EXPECT_EQ(mask[1], GL_FALSE);
  EXPECT_EQ(mask[2], GL_TRUE);
  glDeleteFramebuffers(1, &framebuffer);
}

}  // namespace
}  // namespace radview::gl
