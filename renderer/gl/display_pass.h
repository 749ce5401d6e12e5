#pragma once
// Pass 2 of a frame: pass 1's linear radiosity into display colour, in a full-screen triangle:
// exposure and the sRGB tone map, or a false-colour view (display_views.h): the value, its
// gradient, isolines, the signed difference from the comparison method's image or from a
// reference image, or the standard errors' effect on the display.
#include "core/image.h"
#include "gl/gl_object.h"
#include "gl/render_settings.h"
#include "gl/shader_program.h"

#include <epoxy/gl.h>

namespace radview::gl {

class DisplayPass {
 public:
  // The image a difference view compares with when settings.comparison is Image. Throws Error
  // naming its path for a size this OpenGL cannot hold.
  void setReferenceImage(const ReferenceImage& reference);
  bool hasReferenceImage() const { return referenceTexture_ != 0; }
  const ReferenceImage& referenceImage() const { return reference_; }

  // Into the bound framebuffer, from the texture `linear`; a difference view subtracts
  // `comparison` (the comparison method's linear image), or the reference image where it is 0;
  // the standard-error view reads the standard errors' linear image from `comparison`.
  void draw(const RenderSettings& settings, GLuint linear, GLuint comparison) const;

 private:
  ShaderProgram toneMap_{{"fullscreen.vert", "tonemap.frag"}};
  ShaderProgram falseColour_{{"fullscreen.vert", "false_colour.frag"}};
  GlObject emptyVao_{GlKind::VertexArray};  // the full-screen triangle needs no vertices
  GlObject referenceTexture_;
  ReferenceImage reference_;  // as set
};

}  // namespace radview::gl
