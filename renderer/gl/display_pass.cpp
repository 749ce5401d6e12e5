#include "gl/display_pass.h"

#include "gl/image_transfer.h"

#include <cmath>

namespace radview::gl {

void DisplayPass::setReferenceImage(const ReferenceImage& reference) {
  referenceTexture_ = linearTexture(reference.pixels, reference.path);
  reference_ = reference;
}

void DisplayPass::draw(const RenderSettings& settings, GLuint linear, GLuint comparison) const {
  glDisable(GL_DEPTH_TEST);
  const ShaderProgram& program = settings.view == DisplayView::Normal ? toneMap_ : falseColour_;
  program.set("exposureScale", static_cast<float>(std::exp2(settings.exposure)));
  program.set("background", settings.background);
  program.set("linearRadiosity", 0);
  if (settings.view != DisplayView::Normal) {
    program.set("view", static_cast<int>(settings.view));
    program.set("gradientScale", float(settings.gradientScale));
    program.set("isolineCount", settings.isolineCount);
  }
  if (settings.view == DisplayView::Difference || settings.view == DisplayView::StandardError) {
    program.set("comparisonRadiosity", 1);
    program.set("comparisonLinear", comparison != 0 || reference_.linear ? 1 : 0);
    program.set("differenceScale", float(settings.differenceScale));
    glBindTextureUnit(1, comparison != 0 ? comparison : GLuint(referenceTexture_));
  }
  program.use();
  glBindTextureUnit(0, linear);
  glBindVertexArray(emptyVao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace radview::gl
